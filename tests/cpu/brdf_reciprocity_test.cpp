// Helmholtz reciprocity f(wi, wo) = f(wo, wi) of every model of the reference, on random pairs and on hard
// ones (normal, grazing down to cos = 1e-7, mirror and near-mirror pairs of sharp lobes, retro-reflection),
// with the parameters at both ends of their ranges. Every formula of the contract is symmetric in wi and wo:
// h = wi + wo, the max(cos_i, cos_o) of Ashikhmin-Shirley and the sqrt(cos_i cos_o) of Ward are symmetric
// functions, R_i.wo = R_o.wi, and V.H = L.H for unit vectors. The one asymmetric operation is V.H, which the
// contract computes as (wo.h)/|h|: swapping wi and wo gives (wi.h)/|h|, equal only for exactly unit vectors.
// Near the grazing mirror configuration (wi ~ -wo in x and y, both cosines tiny) wo.h = 2 (V.H)^2 is tiny and
// the input's own rounding (|w|^2 = 1 + a few ulps) moves it by a relative 3 eps / (V.H)^2: that, and only
// that, is allowed. The test prints how far each model is from exact symmetry, overall and away from that
// configuration (docs/brdfs.md quotes the table).
// Regenerate: ctest --test-dir build/release -R brdf_reciprocity -V
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "reference/terms.h"
#include "reference_materials.h"
#include "support/registry_materials.h"

namespace raylab::test {
namespace {

using reference::dvec3;
using reference::kPi;
using reference::Material;

// Relative asymmetry allowed: 1e-12 (1e4 ulps of rounding) plus the conditioning of V.H = (wo.h)/|h| with
// respect to the inputs' rounding, 3 eps / (V.H)^2, which F, G and 1/(H.L) pass on at most one to one (a margin
// of 4 on top).
constexpr double kTolerance = 1e-12;
constexpr double kEpsilon = 2.220446049250313e-16;

double allowedAsymmetry(const dvec3& wi, const dvec3& wo) {
  const double VoH = 0.5 * glm::length(wi + wo);  // = V.H for unit vectors, well conditioned
  return kTolerance + 12.0 * kEpsilon / (VoH * VoH);
}

dvec3 directionFromCos(double c, double phi) {
  const double s = std::sqrt((1.0 - c) * (1.0 + c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}

std::vector<std::pair<std::string, std::vector<ParamValue>>> materialsUnderTest() {
  std::vector<std::pair<std::string, std::vector<ParamValue>>> list;
  const std::vector<ParamValue> rho = {{"rho_d", 0.2}, {"rho_s", 0.8}};
  auto with = [&rho](std::vector<ParamValue> more) {
    more.insert(more.end(), rho.begin(), rho.end());
    return more;
  };
  list.push_back({"lambert", {{"rho_d", 0.7}}});
  for (double s : {1.0, 50.0, 10000.0}) {
    list.push_back({"phong", with({{"s", s}})});
    list.push_back({"blinnphong", with({{"s", s}})});
  }
  for (double m : {0.001, 0.2, 1.0}) {
    for (double eta : {1.0, 1.5, 10.0}) list.push_back({"cooktorrance", with({{"m", m}, {"eta", eta}})});
  }
  for (const char* model : {"ward", "ward_duer", "ward_gmd"}) {
    for (auto [ax, ay] : {std::pair{0.001, 0.001}, {0.2, 0.2}, {1.0, 1.0}, {0.001, 1.0}, {0.1, 0.4}}) {
      list.push_back({model, with({{"alpha_x", ax}, {"alpha_y", ay}})});
    }
  }
  for (auto [nu, nv] : {std::pair{1.0, 1.0}, {100.0, 100.0}, {10000.0, 10000.0}, {1.0, 10000.0}, {10.0, 1000.0}}) {
    list.push_back({"ashikhmin_shirley", {{"Rd", 0.3}, {"Rs", 0.6}, {"nu", nu}, {"nv", nv}}});
  }
  std::set<std::string, std::less<>> covered;
  for (const auto& [model, params] : list) covered.insert(model);
  for (const GenericMaterial& generic : uncoveredModelMaterials(covered)) {
    // A model that says it is not reciprocal (its `reciprocal: no` line) is held to what it claims instead, in its
    // own test (openpbr_test).
    if (!findModel(generic.model)->nonReciprocal.empty()) continue;
    std::vector<ParamValue> params;
    for (const auto& [name, value] : generic.params) params.push_back({name, value});
    list.push_back({generic.model, params});
  }
  return list;
}

std::vector<std::pair<dvec3, dvec3>> testPairs() {
  std::vector<std::pair<dvec3, dvec3>> pairs;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Random pairs, uniform over the hemisphere.
  for (int k = 0; k < 4000; ++k) {
    pairs.push_back({directionFromCos(uniform(rng), 2 * kPi * uniform(rng)),
                     directionFromCos(uniform(rng), 2 * kPi * uniform(rng))});
  }
  // Hard pairs: grazing cosines at either or both ends, the normal, mirror and near-mirror pairs (the peak of
  // the sharpest lobes), retro-reflection, and the anisotropic axes.
  const std::vector<double> cosines = {1e-7, 1e-6, 1e-5, 1e-4, 0.01, 0.3, 0.7, 1.0};
  const std::vector<double> phis = {0.0, 0.5 * kPi, kPi, 1.25 * kPi, 0.3};
  for (double ci : cosines) {
    for (double co : cosines) {
      for (double pi : phis) {
        for (double po : phis) pairs.push_back({directionFromCos(ci, pi), directionFromCos(co, po)});
      }
    }
  }
  for (double c : cosines) {
    for (double phi : phis) {
      const dvec3 wo = directionFromCos(c, phi);
      pairs.push_back({dvec3(-wo.x, -wo.y, wo.z), wo});  // mirror
      pairs.push_back({wo, wo});                          // retro-reflection
      for (double offset : {1e-4, 1e-3, 1e-2}) {
        pairs.push_back({directionFromCos(std::min(1.0, c + offset), phi + kPi + offset), wo});
      }
    }
  }
  return pairs;
}

TEST(Reciprocity, EveryModelIsSymmetricInWiAndWo) {
  const auto pairs = testPairs();
  std::map<std::string, double> worstPerModel;
  std::map<std::string, double> worstAwayPerModel;  // V.H > 0.1: away from the grazing mirror configuration
  std::map<std::string, long long> countPerModel;
  for (const auto& [model, params] : materialsUnderTest()) {
    const Material material = makeMaterial(model, params);
    double worst = 0.0;
    double worstAway = 0.0;
    for (const auto& [wi, wo] : pairs) {
      const dvec3 forward = reference::eval(material, wi, wo);
      const dvec3 backward = reference::eval(material, wo, wi);
      for (int c = 0; c < 3; ++c) {
        const double scale = std::max(std::abs(forward[c]), std::abs(backward[c]));
        if (scale == 0.0) continue;
        const double relative = std::abs(forward[c] - backward[c]) / scale;
        worst = std::max(worst, relative);
        if (0.5 * glm::length(wi + wo) > 0.1) worstAway = std::max(worstAway, relative);
        EXPECT_LE(relative, allowedAsymmetry(wi, wo))
            << materialLabel(model, params) << " wi = (" << wi.x << ", " << wi.y << ", " << wi.z << ") wo = (" << wo.x
            << ", " << wo.y << ", " << wo.z << ")";
      }
    }
    worstPerModel[model] = std::max(worstPerModel[model], worst);
    worstAwayPerModel[model] = std::max(worstAwayPerModel[model], worstAway);
    countPerModel[model] += static_cast<long long>(pairs.size());
  }
  std::printf("Reciprocity: largest relative |f(wi,wo) - f(wo,wi)| / max per model, over all pairs and over those\n"
              "with V.H > 0.1 (away from the grazing mirror configuration)\n");
  for (const auto& [model, worst] : worstPerModel) {
    std::printf("  %-18s all %.2e   V.H > 0.1: %.2e   (%lld pairs)\n", model.c_str(), worst,
                worstAwayPerModel[model], countPerModel[model]);
  }
  // Every registered model with an f (delta BSDFs are tested in glass_physics_test) that claims to be reciprocal.
  std::size_t withF = 0;
  for (const ModelInfo& model : allModels()) withF += isDeltaOnly(model) || !model.nonReciprocal.empty() ? 0 : 1;
  EXPECT_EQ(worstPerModel.size(), withF);
}

// The test can fail: a deliberately non-reciprocal variant (Phong's f times cos_o, the classic slip of folding
// a cosine into f) is caught by the same comparison.
TEST(Reciprocity, DetectsANonReciprocalVariant) {
  const Material material = makeMaterial("phong", {{"rho_d", 0.2}, {"rho_s", 0.8}, {"s", 50}});
  auto nonReciprocal = [&material](const dvec3& wi, const dvec3& wo) {
    return reference::eval(material, wi, wo) * wo.z;
  };
  double worst = 0.0;
  for (const auto& [wi, wo] : testPairs()) {
    const double a = nonReciprocal(wi, wo).x;
    const double b = nonReciprocal(wo, wi).x;
    if (std::max(a, b) > 0.0) worst = std::max(worst, std::abs(a - b) / std::max(a, b));
  }
  EXPECT_GT(worst, kTolerance);
}

}  // namespace
}  // namespace raylab::test
