// Importance sampling of the GLSL library on the device (bsdfSample, brdf_sample.comp), issue 3 item 6: for
// every model and incident directions normal, oblique (45 deg) and grazing (85 deg) (rough glass: and from inside,
// 120 and 160 deg), 10^6 device samples
// tested by χ² against the REFERENCE pdf (tests/support/chi2.h: a 20 x 40 grid in (cos theta, phi), cells
// expecting fewer than 5 samples pooled, failed samples as one more cell, alpha = 0.01 with Šidák's correction
// over all the cases below). Every sample must carry bsdfEval and bsdfPdf of its own direction (evaluated
// again by the kernel), and its pdf must match the reference pdf within 1e-3. The uniform numbers come from
// the host, so the same u also drives the reference sampler: the directions are compared too.
// Regenerate the p-values: ctest --test-dir build/release -R brdf_device_sampling -V
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "brdf_eval/device_evaluator.h"
#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "brdf_params/material_params.h"
#include "support/chi2.h"
#include "support/gpu_test.h"
#include "support/measured_files.h"
#include "support/registry_materials.h"

namespace raylab::test {
namespace {

using glm::dvec3;
using glm::vec3;

constexpr std::uint32_t kSamples = 1000000;
constexpr double kWeightTolerance = 1e-3;

struct Param {
  const char* name;
  float value;  // every channel of an RGB parameter
};

struct SamplingCase {
  const char* model;
  std::vector<Param> params;
  double thetaDeg;
};

// Moderate lobes that a 20 x 40 grid resolves, with and without the diffuse lobe mixed in.
std::vector<SamplingCase> samplingCases() {
  const std::vector<std::pair<const char*, std::vector<Param>>> materials = {
      {"lambert", {{"rho_d", 0.5f}}},
      {"phong", {{"rho_d", 0.4f}, {"rho_s", 0.6f}, {"s", 20.0f}}},
      {"phong", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"s", 200.0f}}},
      {"blinnphong", {{"rho_d", 0.4f}, {"rho_s", 0.6f}, {"s", 20.0f}}},
      {"blinnphong", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"s", 200.0f}}},
      {"cooktorrance", {{"rho_d", 0.4f}, {"rho_s", 0.6f}, {"m", 0.3f}, {"eta", 1.5f}}},
      {"cooktorrance", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"m", 0.1f}, {"eta", 1.5f}}},
      {"ward", {{"rho_d", 0.4f}, {"rho_s", 0.6f}, {"alpha_x", 0.1f}, {"alpha_y", 0.4f}}},
      {"ward_duer", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"alpha_x", 0.3f}, {"alpha_y", 0.3f}}},
      {"ward_gmd", {{"rho_d", 0.4f}, {"rho_s", 0.6f}, {"alpha_x", 0.4f}, {"alpha_y", 0.1f}}},
      {"ashikhmin_shirley", {{"Rd", 0.4f}, {"Rs", 0.6f}, {"nu", 20.0f}, {"nv", 200.0f}}},
      {"ashikhmin_shirley", {{"Rd", 0.0f}, {"Rs", 1.0f}, {"nu", 100.0f}, {"nv", 100.0f}}},
      {"oren_nayar", {{"rho_d", 0.8f}, {"sigma", 1.0f}}},
      {"eon", {{"rho_d", 0.8f}, {"r", 1.0f}}},
      {"gltf_pbr", {{"base_color", 0.6f}, {"metallic", 0.0f}, {"roughness", 0.5f}, {"ior", 1.5f}}},
      {"gltf_pbr", {{"base_color", 0.9f}, {"metallic", 1.0f}, {"roughness", 0.3f}}},
      {"ggx_conductor", {{"alpha_x", 0.3f}, {"alpha_y", 0.3f}}},
      {"ggx_conductor", {{"alpha_x", 0.1f}, {"alpha_y", 0.5f}, {"eta", 1.5f}, {"k", 0.0f}}},
      {"ggx_dielectric", {{"alpha_x", 0.3f}, {"alpha_y", 0.3f}, {"eta", 1.5f}}},
      {"ggx_dielectric", {{"alpha_x", 0.1f}, {"alpha_y", 0.4f}, {"eta", 1.33f}, {"tint", 0.5f}}},
      {"abc_microfacet", {{"rho_d", 0.4f}, {"a", 2.0f}, {"b", 100.0f}, {"c", 1.5f}, {"ior", 1.5f}}},
      {"abc_microfacet", {{"rho_d", 0.0f}, {"a", 1.0f}, {"b", 30.0f}, {"c", 0.5f}, {"ior", 10.0f}}},
      // A coated anisotropic dielectric, its coat of its own frame (a coat normal map's tilt, a turned anisotropy:
      // the coat's lobe sampled in that frame), and a half-coated metal under an anisotropic coat: both GGX lobes.
      {"openpbr", {{"base_color", 0.6f}, {"specular_roughness", 0.5f}, {"specular_roughness_anisotropy", 0.5f},
                   {"coat_weight", 1.0f}, {"coat_roughness", 0.2f}, {"coat_roughness_anisotropy", 0.6f},
                   {"geometry_coat_normal_x", 0.4f}, {"geometry_coat_normal_y", -0.2f},
                   {"geometry_coat_tangent_angle", 1.0f}}},
      {"openpbr", {{"base_color", 0.9f}, {"base_metalness", 1.0f}, {"specular_roughness", 0.4f},
                   {"coat_weight", 0.5f}, {"coat_roughness", 0.3f}, {"coat_roughness_anisotropy", 0.6f}}},
      // Fuzz over a coated diffuse base: the fuzz's LTC as a third lobe.
      {"openpbr", {{"base_color", 0.5f}, {"coat_weight", 1.0f}, {"coat_roughness", 0.1f}, {"fuzz_weight", 1.0f},
                   {"fuzz_roughness", 0.4f}, {"fuzz_color", 0.9f}}},
      // A translucent base under a coat: the interface's reflection and refraction beside the reflection's mixture,
      // from outside and from inside.
      {"openpbr", {{"base_color", 0.5f}, {"specular_roughness", 0.4f}, {"transmission_weight", 0.8f},
                   {"transmission_color", 0.7f}, {"coat_weight", 0.5f}, {"coat_roughness", 0.2f}}},
      // A thin wall, half translucent and half a subsurface sheet: through it straight and diffusely, from both faces.
      {"openpbr", {{"base_color", 0.5f}, {"specular_roughness", 0.3f}, {"transmission_weight", 0.5f},
                   {"subsurface_weight", 1.0f}, {"subsurface_color", 0.8f}, {"geometry_thin_walled", 1.0f}}},
      // A sheet that passes everything (glTF's diffuse transmission): the mirrored share at its cap of 0.9, the
      // reflection's specular lobe still sampled.
      {"openpbr", {{"base_color", 0.5f}, {"specular_roughness", 0.3f}, {"subsurface_weight", 1.0f},
                   {"subsurface_color", 0.8f}, {"geometry_thin_walled", 1.0f}, {"subsurface_scatter_anisotropy", 1.0f}}},
      // A dispersive solid, its spread exaggerated (V = 4) so that the channels' lobes part: a channel drawn per
      // sample, the density the channels' mean.
      {"openpbr", {{"specular_roughness", 0.3f}, {"transmission_weight", 1.0f}, {"transmission_dispersion_scale", 1.0f},
                   {"transmission_dispersion_abbe_number", 4.0f}}},
  };
  std::vector<SamplingCase> cases;
  std::set<std::string, std::less<>> covered;
  for (const auto& [model, params] : materials) {
    covered.insert(model);
    for (double theta : samplingAngles(model)) cases.push_back({model, params, theta});
  }
  for (const GenericMaterial& generic : uncoveredModelMaterials(covered)) {
    std::vector<Param> params;
    for (const auto& [name, value] : generic.params) params.push_back({name.data(), float(value)});
    const char* model = findModel(generic.model)->name.data();  // the registry's names are string literals
    for (double theta : samplingAngles(model)) cases.push_back({model, params, theta});
  }
  return cases;
}

gpu::MaterialRecord makeRecord(const SamplingCase& c) {
  gpu::MaterialRecord record = defaultRecord(findModel(c.model)->id);
  for (const Param& p : c.params) setParam(record, p.name, glm::vec3(p.value), c.model);
  return record;
}

std::string label(const SamplingCase& c) {
  std::string text = c.model;
  for (const Param& p : c.params) {
    char value[96];  // openpbr's names reach 30 characters
    std::snprintf(value, sizeof value, " %s=%g", p.name, p.value);
    text += value;
  }
  return text;
}

// Uniform floats in [0, 1) with 24 random bits: exactly the values the device reads.
std::vector<vec3> uniforms(std::uint64_t seed, std::size_t count) {
  std::mt19937_64 rng(seed);
  const auto next = [&] { return static_cast<float>(rng() >> 40) * 0x1p-24f; };
  std::vector<vec3> u(count);
  for (vec3& v : u) v = vec3(next(), next(), next());
  return u;
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-30); }

class BrdfDeviceSampling : public GpuTest, public ::testing::WithParamInterface<SamplingCase> {
 protected:
  // One sampler (one pipeline) for the whole suite, created by the first test, destroyed before the device.
  static BrdfSampler& sampler() {
    if (sampler_ == nullptr) sampler_ = new BrdfSampler(createBrdfSampler(device(), kSamples));
    return *sampler_;
  }
  static void TearDownTestSuite() {
    if (sampler_ != nullptr) {
      destroyBrdfSampler(device(), *sampler_);
      delete sampler_;
      sampler_ = nullptr;
    }
    GpuTest::TearDownTestSuite();
  }
  static BrdfSampler* sampler_;
};

BrdfSampler* BrdfDeviceSampling::sampler_ = nullptr;

// True when f changes within 64 float ulps of 1 of wi or wo (one component at a time, the absolute error of the
// device's angles): a tabulated model (measured) is a step function, and within rounding of a bin edge the device
// may take either bin. At normal incidence every pair lies on the table's phi_d = 0 / pi edge (docs/brdfs.md).
bool nearStep(const reference::Material& material, const dvec3& wi, const dvec3& wo, const dvec3& f) {
  for (int which = 0; which < 2; ++which) {
    for (int j = 0; j < 3; ++j) {
      for (double sign : {-1.0, 1.0}) {
        dvec3 a = wi, b = wo;
        dvec3& w = which == 0 ? a : b;
        w[j] += sign * 64.0 * 0x1p-23;
        if (reference::eval(material, a, b) != f) return true;
      }
    }
  }
  return false;
}

TEST_P(BrdfDeviceSampling, MatchesTheReferencePdf) {
  const SamplingCase& c = GetParam();
  const bool twoSided = isTwoSided(*findModel(c.model));
  const gpu::MaterialRecord record = makeRecord(c);
  const reference::Material material = reference::fromRecord(record);
  // phi_o = 30 deg keeps wo off the anisotropic axes.
  const double theta = c.thetaDeg * M_PI / 180.0;
  const vec3 wo(float(std::sin(theta) * std::cos(M_PI / 6)), float(std::sin(theta) * std::sin(M_PI / 6)),
                float(std::cos(theta)));
  const dvec3 woRef(wo);
  const std::vector<vec3> u = uniforms(std::hash<std::string>{}(label(c)) + std::uint64_t(c.thetaDeg), kSamples);
  const std::vector<gpu::BrdfSampleValue> samples = drawBrdfSamples(device(), sampler(), record, wo, u);
  ASSERT_EQ(samples.size(), kSamples);

  std::vector<dvec3> directions;
  directions.reserve(kSamples);
  int bad = 0;
  double worstSelf = 0.0, worstPdf = 0.0, worstF = 0.0;
  std::size_t directionMismatches = 0, stepCases = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const gpu::BrdfSampleValue& s = samples[k];
    const bool finite = std::isfinite(s.pdf) && s.pdf >= 0.0f && std::isfinite(s.f.x) && std::isfinite(s.f.y) &&
                        std::isfinite(s.f.z) && s.f.x >= 0.0f && s.f.y >= 0.0f && s.f.z >= 0.0f;
    if (!finite || (s.pdf > 0.0f && !(twoSided ? s.wi.z != 0.0f : s.wi.z > 0.0f))) {
      if (++bad <= 5) ADD_FAILURE() << "sample " << k << ": pdf " << s.pdf << " wi.z " << s.wi.z << " f " << s.f.x;
      continue;
    }
    // The reference sampler fed the same u: the same strategy must give the same direction (rare
    // differences at the lobe choice u.x = pSpec or where float and double round a boundary differently).
    if (k % 10 == 0) {
      const reference::Sample r = reference::sample(material, woRef, dvec3(u[k]));
      const bool same = (r.pdf > 0.0) == (s.pdf > 0.0f) && (r.pdf == 0.0 || glm::length(r.wi - dvec3(s.wi)) < 1e-3);
      directionMismatches += same ? 0 : 1;
    }
    if (s.pdf == 0.0f) continue;
    const dvec3 wi(s.wi);
    directions.push_back(glm::normalize(wi));
    worstSelf = std::max({worstSelf, relative(s.pdf, s.evalPdf), relative(s.f.x, s.evalF.x),
                          relative(s.f.y, s.evalF.y), relative(s.f.z, s.evalF.z)});
    if (k % 10 == 0) {
      worstPdf = std::max(worstPdf, relative(s.pdf, reference::pdf(material, wi, woRef)));
      const dvec3 f = reference::eval(material, wi, woRef);
      if (reference::isTabulated(material) && nearStep(material, wi, woRef, f)) {
        ++stepCases;
      } else {
        // Each channel against the largest: where a dispersive solid's channels part, a sample in one channel's lobe
        // meets the others far in their tails, where float's rounding of the refraction is a large share of a tiny
        // value and a vanishing share of the light the sample carries.
        const double largest = std::max({f.x, f.y, f.z});
        for (int ch = 0; ch < 3; ++ch) worstF = std::max(worstF, relative(s.f[ch], f[ch]) * std::min(1.0, f[ch] / largest));
      }
    }
  }

  Chi2Options options;
  options.thetaCells = 20;
  options.phiCells = 40;
  options.significance = 0.01;
  options.testCount = static_cast<int>(samplingCases().size());
  const Chi2Result result =
      chi2Test(directions, kSamples, [&](const dvec3& wi) { return reference::pdf(material, wi, woRef); }, options);
  std::printf("%-52s theta_o %2g: p = %.4f (chi2 %.1f, dof %d, %.2f%% failed); sample vs eval/pdf %.1e, pdf vs "
              "reference %.1e, f vs reference %.1e (%zu at a table's bin edge), directions unlike the reference's %.4f%%\n",
              label(c).c_str(), c.thetaDeg, result.pValue, result.statistic, result.degreesOfFreedom,
              100.0 * (1.0 - double(directions.size()) / kSamples), worstSelf, worstPdf, worstF, stepCases,
              100.0 * directionMismatches / (kSamples / 10));
  EXPECT_EQ(bad, 0) << "NaN, Inf, negative or below-horizon (two-sided: on-the-surface) samples";
  EXPECT_LE(worstSelf, kWeightTolerance) << "a sample's f or pdf differs from bsdfEval/bsdfPdf at its direction";
  EXPECT_LE(worstPdf, kWeightTolerance) << "the device pdf differs from the reference pdf";
  EXPECT_LE(worstF, kWeightTolerance) << "the sample's f differs from the reference f";
  EXPECT_LE(directionMismatches, kSamples / 10 / 1000) << "the device and the reference sample differently";
  EXPECT_TRUE(result.passed) << result.report;
}

INSTANTIATE_TEST_SUITE_P(EveryModel, BrdfDeviceSampling, ::testing::ValuesIn(samplingCases()),
                         [](const ::testing::TestParamInfo<SamplingCase>& info) {
                           std::string name = std::string(info.param.model) + "_" + std::to_string(info.index) +
                                              "_theta" + std::to_string(static_cast<int>(info.param.thetaDeg));
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

// bsdfSample at degenerate inputs: parameters at both ends of their ranges, wo at the normal, grazing (down to
// 1e-30), on and below the horizon, and u at 0 and just below 1. Every sample is finite and non-negative; a
// successful one lies above the horizon (a two-sided model's: off the surface, from wo off it), is unit length and
// carries bsdfEval and bsdfPdf of its direction; a failed one carries nothing.
class BrdfDeviceSamplingRobustness : public GpuTest {};

TEST_F(BrdfDeviceSamplingRobustness, DegenerateInputsGiveFiniteSamplesOrNone) {
  const std::vector<std::vector<Param>> scalarSets = {
      {},  // the defaults (and the only set for lambert and glass)
      {{"s", 1.0f}}, {{"s", 10000.0f}}, {{"m", 0.001f}}, {{"m", 1.0f}, {"eta", 10.0f}},
      {{"alpha_x", 0.001f}, {"alpha_y", 1.0f}}, {{"alpha_x", 0.001f}, {"alpha_y", 0.001f}}, {{"alpha_x", 1.0f}, {"alpha_y", 1.0f}},
      {{"nu", 1.0f}, {"nv", 10000.0f}}, {{"nu", 10000.0f}, {"nv", 10000.0f}}, {{"nu", 1.0f}, {"nv", 1.0f}},
      {{"sigma", 1.5f}}, {{"r", 1.0f}}, {{"roughness", 0.0f}, {"metallic", 1.0f}}, {{"roughness", 1.0f}, {"ior", 1.0f}},
      {{"alpha_x", 0.001f}, {"alpha_y", 0.001f}, {"eta", 0.01f}, {"k", 20.0f}},
      {{"alpha_x", 0.001f}, {"alpha_y", 0.001f}, {"eta", 1.001f}}, {{"alpha_x", 1.0f}, {"alpha_y", 1.0f}, {"eta", 10.0f}}};
  const float last = 1.0f - 0x1p-24f;
  std::vector<vec3> u;
  for (float x : {0.0f, 0.5f, last}) {
    for (float y : {0.0f, 0.25f, last}) {
      for (float z : {0.0f, 0.3f, last}) u.push_back(vec3(x, y, z));
    }
  }
  for (const vec3& v : uniforms(99, 2000)) u.push_back(v);
  const vec3 wos[] = {vec3(0.0f, 0.0f, 1.0f), vec3(0.6f, 0.0f, 0.8f), vec3(1.0f, 0.0f, 1e-7f), vec3(0.0f, 1.0f, 1e-30f),
                      vec3(1.0f, 0.0f, 0.0f), vec3(0.6f, 0.0f, -0.8f)};
  BrdfSampler sampler = createBrdfSampler(device(), static_cast<std::uint32_t>(u.size()));
  int bad = 0;
  std::size_t drawn = 0, successful = 0;
  for (const ModelInfo& model : allModels()) {
    for (const auto& scalars : scalarSets) {
      for (const auto& [d, sp] : {std::pair{0.0f, 0.0f}, std::pair{1.0f, 1.0f}, std::pair{0.0f, 1.0f}}) {
        gpu::MaterialRecord record = defaultRecord(model.id);
        for (const ParamInfo& p : model.params) {
          if (isFileParam(p)) setParam(record, p.name, glm::vec3(float(testFileFor(p, 0))), "test");
        }
        bool applies = true;
        for (const Param& p : scalars) applies = applies && findParam(model, p.name) != nullptr;
        if (!applies) continue;
        for (const Param& p : scalars) setParam(record, p.name, glm::vec3(p.value), std::string(model.name));
        // The diffuse colour d, the model's other colours (a specular lobe's weight or F0, an index) sp, within
        // their ranges.
        for (const ParamInfo& p : model.params) {
          if (p.rgb && !isDeltaOnly(model) && findParam(model, p.name) != nullptr &&
              std::none_of(scalars.begin(), scalars.end(), [&](const Param& s) { return p.name == s.name; })) {
            setParam(record, p.name, glm::vec3(std::clamp(p.role == "diffuse" ? d : sp, p.min, p.max)), "test");
          }
        }
        for (const vec3& wo : wos) {
          const std::vector<gpu::BrdfSampleValue> samples = drawBrdfSamples(device(), sampler, record, wo, u);
          for (const gpu::BrdfSampleValue& s : samples) {
            ++drawn;
            const bool finite = std::isfinite(s.pdf) && s.pdf >= 0.0f && std::isfinite(s.f.x) && std::isfinite(s.f.y) &&
                                std::isfinite(s.f.z) && glm::all(glm::greaterThanEqual(s.f, vec3(0.0f)));
            bool ok = finite;
            if (ok && s.pdf > 0.0f) {
              ++successful;
              const bool sides = isTwoSided(model) ? wo.z != 0.0f && s.wi.z != 0.0f : wo.z > 0.0f && s.wi.z > 0.0f;
              ok = sides && std::abs(glm::length(s.wi) - 1.0f) < 1e-5f &&
                   relative(s.pdf, s.evalPdf) <= kWeightTolerance && relative(s.f.x, s.evalF.x) <= kWeightTolerance;
            } else if (ok) {
              ok = s.wi == vec3(0.0f) && s.f == vec3(0.0f);
            }
            if (!ok && ++bad <= 10) {
              ADD_FAILURE() << model.name << " wo " << wo.x << " " << wo.y << " " << wo.z << ": pdf " << s.pdf << " wi "
                            << s.wi.x << " " << s.wi.y << " " << s.wi.z << " f " << s.f.x << " (eval " << s.evalF.x
                            << ", pdf " << s.evalPdf << ")";
            }
          }
        }
      }
    }
  }
  destroyBrdfSampler(device(), sampler);
  std::printf("degenerate sampling inputs: %zu samples (%zu successful), %d NaN/Inf/negative or inconsistent\n", drawn,
              successful, bad);
  EXPECT_EQ(bad, 0);
  EXPECT_GT(successful, drawn / 4);
}

}  // namespace
}  // namespace raylab::test
