// Importance sampling of the reference (reference::sample / pdf) for every model, by χ² goodness of fit in the
// manner of pbrt-v4 and Mitsuba 3: 10^6 samples per case from std::mt19937_64, a 20 x 40 grid in
// (cos theta, phi), cells expecting fewer than 5 samples pooled, failed samples as one more cell, alpha = 0.01
// with Šidák's correction over all the cases below. Incident directions normal, oblique (45 deg) and grazing
// (85 deg), and from inside for rough glass; moderate parameters, with the diffuse lobe mixed in or not. Each case also checks that a sample
// carries eval() and pdf() of its direction and that the pdf integrates to at most 1.
// Regenerate the p-values: ctest --test-dir build/release -R brdf_sampling -V
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "reference/terms.h"
#include "reference_materials.h"
#include "support/registry_materials.h"
#include "support/chi2.h"

namespace raylab::test {
namespace {

using reference::dvec3;
using reference::kPi;
using reference::Material;

constexpr std::size_t kSamples = 1000000;
constexpr std::size_t kConsistencyChecks = 20000;  // samples whose f and pdf are compared with eval and pdf

struct SamplingCase {
  std::string model;
  std::vector<ParamValue> params;
  double thetaDeg;
};

std::vector<SamplingCase> samplingCases() {
  const std::vector<std::pair<std::string, std::vector<ParamValue>>> materials = {
      {"lambert", {{"rho_d", 0.5}}},
      {"phong", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"s", 20}}},
      {"phong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 200}}},
      {"blinnphong", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"s", 20}}},
      {"blinnphong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 200}}},
      {"cooktorrance", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"m", 0.3}, {"eta", 1.5}}},
      {"cooktorrance", {{"rho_d", 0}, {"rho_s", 1}, {"m", 0.1}, {"eta", 1.5}}},
      {"ward", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"alpha_x", 0.1}, {"alpha_y", 0.4}}},
      {"ward", {{"rho_d", 0}, {"rho_s", 1}, {"alpha_x", 0.3}, {"alpha_y", 0.3}}},
      {"ward_duer", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"alpha_x", 0.1}, {"alpha_y", 0.4}}},
      {"ward_gmd", {{"rho_d", 0.4}, {"rho_s", 0.6}, {"alpha_x", 0.1}, {"alpha_y", 0.4}}},
      {"ashikhmin_shirley", {{"Rd", 0.4}, {"Rs", 0.6}, {"nu", 20}, {"nv", 200}}},
      {"ashikhmin_shirley", {{"Rd", 0}, {"Rs", 1}, {"nu", 100}, {"nv", 100}}},
      {"oren_nayar", {{"rho_d", 0.8}, {"sigma", 1.0}}},
      {"eon", {{"rho_d", 0.8}, {"r", 1.0}}},
      {"gltf_pbr", {{"base_color", 0.6}, {"metallic", 0}, {"roughness", 0.5}, {"ior", 1.5}}},
      {"gltf_pbr", {{"base_color", 0.9}, {"metallic", 1}, {"roughness", 0.3}}},
      {"ggx_conductor", {{"alpha_x", 0.3}, {"alpha_y", 0.3}}},
      {"ggx_conductor", {{"alpha_x", 0.1}, {"alpha_y", 0.5}, {"eta", 1.5}, {"k", 0}}},
      {"ggx_dielectric", {{"alpha_x", 0.3}, {"alpha_y", 0.3}, {"eta", 1.5}}},
      {"ggx_dielectric", {{"alpha_x", 0.1}, {"alpha_y", 0.4}, {"eta", 1.33}, {"tint", 0.5}}},
      // C below, at and above 1: the three forms of the inverse CDF.
      {"abc_microfacet", {{"rho_d", 0.4}, {"a", 2}, {"b", 100}, {"c", 1.5}, {"ior", 1.5}}},
      {"abc_microfacet", {{"rho_d", 0}, {"a", 1}, {"b", 30}, {"c", 0.5}, {"ior", 10}}},
      {"abc_microfacet", {{"rho_d", 0.2}, {"a", 5}, {"b", 200}, {"c", 1}, {"ior", 1.5}}},
      {"abc_smooth", {{"rho_d", 0.4}, {"a", 2}, {"b", 50}, {"c", 1}, {"ior", 1.5}}},
      {"abc_smooth", {{"rho_d", 0}, {"a", 1}, {"b", 300}, {"c", 0.5}, {"ior", 5}}},
      // A coated anisotropic dielectric, and a half-coated metal under an anisotropic coat: both GGX lobes sampled.
      {"openpbr", {{"base_color", 0.6}, {"specular_roughness", 0.5}, {"specular_roughness_anisotropy", 0.5},
                   {"coat_weight", 1}, {"coat_roughness", 0.2}}},
      {"openpbr", {{"base_color", 0.9}, {"base_metalness", 1}, {"specular_roughness", 0.4}, {"coat_weight", 0.5},
                   {"coat_roughness", 0.3}, {"coat_roughness_anisotropy", 0.6}}},
  };
  std::vector<SamplingCase> cases;
  std::set<std::string, std::less<>> covered;
  for (const auto& [model, params] : materials) {
    covered.insert(model);
    for (double theta : samplingAngles(model)) cases.push_back({model, params, theta});
  }
  for (const GenericMaterial& generic : uncoveredModelMaterials(covered)) {
    std::vector<ParamValue> params;
    for (const auto& [name, value] : generic.params) params.push_back({name, value});
    for (double theta : {0.0, 45.0, 85.0}) cases.push_back({generic.model, params, theta});
  }
  return cases;
}

class Sampling : public ::testing::TestWithParam<SamplingCase> {};

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }  // [0, 1)

TEST_P(Sampling, MatchesItsPdf) {
  const SamplingCase& c = GetParam();
  const Material material = makeMaterial(c.model, c.params);
  // phi_o = 30 deg keeps wo off the anisotropic axes.
  const double theta = c.thetaDeg * kPi / 180.0;
  const dvec3 wo(std::sin(theta) * std::cos(kPi / 6), std::sin(theta) * std::sin(kPi / 6), std::cos(theta));
  std::mt19937_64 rng(std::hash<std::string>{}(materialLabel(c.model, c.params)) + static_cast<unsigned>(c.thetaDeg));

  std::vector<dvec3> directions;
  directions.reserve(kSamples);
  double worstF = 0.0;
  double worstPdf = 0.0;
  for (std::size_t k = 0; k < kSamples; ++k) {
    const dvec3 u(uniform01(rng), uniform01(rng), uniform01(rng));
    const reference::Sample s = reference::sample(material, wo, u);
    if (s.pdf == 0.0) continue;
    directions.push_back(s.wi);
    if (k >= kConsistencyChecks) continue;
    const dvec3 f = reference::eval(material, s.wi, wo);
    const double p = reference::pdf(material, s.wi, wo);
    for (int ch = 0; ch < 3; ++ch) {
      if (f[ch] > 0.0) worstF = std::max(worstF, std::abs(s.f[ch] - f[ch]) / f[ch]);
    }
    worstPdf = std::max(worstPdf, std::abs(s.pdf - p) / p);
  }
  EXPECT_LE(worstF, 1e-3) << "sample().f differs from eval()";
  EXPECT_LE(worstPdf, 1e-3) << "sample().pdf differs from pdf()";

  Chi2Options options;
  options.thetaCells = 20;
  options.phiCells = 40;
  options.significance = 0.01;
  options.testCount = static_cast<int>(samplingCases().size());
  const Chi2Result result =
      chi2Test(directions, kSamples, [&](const dvec3& wi) { return reference::pdf(material, wi, wo); }, options);
  std::printf("%-58s theta_o %4g: p = %.4f  (chi2 %.1f, dof %d, integral of pdf %.6f, %.2f%% failed)\n",
              materialLabel(c.model, c.params).c_str(), c.thetaDeg, result.pValue, result.statistic,
              result.degreesOfFreedom, result.pdfIntegral, 100.0 * (1.0 - double(directions.size()) / kSamples));
  EXPECT_LE(result.pdfIntegral, 1.0 + 1e-6);
  EXPECT_TRUE(result.passed) << result.report;
}

INSTANTIATE_TEST_SUITE_P(EveryModel, Sampling, ::testing::ValuesIn(samplingCases()),
                         [](const ::testing::TestParamInfo<SamplingCase>& info) {
                           std::string name = info.param.model + "_" + std::to_string(info.index) + "_theta" +
                                              std::to_string(static_cast<int>(info.param.thetaDeg));
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace raylab::test
