// `raylab brdf fit` (engine/fit): MERL files written from known models by the project's own writer are fitted back,
// the generating model ranks first and its parameters come back within 1e-3 (noise-free) or a stated bound (with
// noise); the same seed gives the same fits; bad targets are refused with the file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "brdf_params/material_params.h"
#include "fit/fit.h"
#include "fit/fit_plan.h"
#include "fit/fit_search.h"
#include "fit_test_support.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "support/error_text.h"
#include "util/error.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) { return scratchFile("fit_test", name); }

gpu::MaterialRecord material(const std::string& model, const std::string& params) { return materialOf(model, params); }

// A MERL file of `record`, each stored sample times (1 + noise * N(0, 1)) when noise > 0 (fixed seed).
std::string merlFileOf(const gpu::MaterialRecord& record, const std::string& name, double noise = 0.0) {
  const reference::Material m = reference::fromRecord(record);
  MerlTable table = tabulateMerl([&](const glm::dvec3& wi, const glm::dvec3& wo) { return reference::eval(m, wi, wo); });
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  if (noise > 0.0) {
    for (double& v : table.stored) {
      if (v >= 0.0) v = std::max(0.0, v * (1.0 + noise * normal(random)));
    }
  }
  const std::string path = scratch(name);
  writeMerl(path, table);
  return path;
}

double param(const FitResult& fit, const std::string& name, int channel = 0) {
  return getParam(fit.record, name)[channel];
}

FitOptions options(std::vector<std::string> models, int starts = 4) {
  FitOptions o;
  o.models = std::move(models);
  o.starts = starts;
  return o;
}

TEST(BrdfFit, RecoversIsotropicGgxFromAMerlFileAndRanksItFirst) {
  const std::string path = merlFileOf(material("ggx_conductor", "alpha_x=0.15,alpha_y=0.15,metal=Au"), "ggx.binary");
  const std::vector<FitResult> fits = fitModels(merlFitTarget(path), options({"cooktorrance", "ggx_conductor", "ward"}));
  ASSERT_EQ(fits.size(), 3u);
  EXPECT_EQ(fits[0].model, "ggx_conductor");
  EXPECT_LT(fits[0].relativeError, 1e-6);
  EXPECT_GT(fits[1].relativeError, 0.05) << "the other models cannot be this close";
  EXPECT_NEAR(param(fits[0], "alpha_x"), 0.15, 0.15e-3);
  EXPECT_NEAR(param(fits[0], "alpha_y"), 0.15, 0.15e-3);
  const glm::vec3 eta = getParam(material("ggx_conductor", "metal=Au"), "eta");
  const glm::vec3 k = getParam(material("ggx_conductor", "metal=Au"), "k");
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(param(fits[0], "eta", c), eta[c], 1e-3 * eta[c]) << c;
    EXPECT_NEAR(param(fits[0], "k", c), k[c], 1e-3 * k[c]) << c;
  }
}

TEST(BrdfFit, RecoversCookTorranceFromAMerlFileAndRanksItFirst) {
  const std::string path = merlFileOf(material("cooktorrance", "rho_d=0.2/0.3/0.1,rho_s=0.8,m=0.3,eta=1.5"), "ct.binary");
  const std::vector<FitResult> fits = fitModels(merlFitTarget(path), options({"blinnphong", "cooktorrance", "gltf_pbr"}));
  EXPECT_EQ(fits[0].model, "cooktorrance");
  EXPECT_LT(fits[0].relativeError, 1e-6);
  EXPECT_NEAR(param(fits[0], "m"), 0.3, 0.3e-3);
  EXPECT_NEAR(param(fits[0], "eta"), 1.5, 1.5e-3);
  EXPECT_NEAR(param(fits[0], "rho_s"), 0.8, 0.8e-3);
  EXPECT_NEAR(param(fits[0], "rho_d", 0), 0.2, 0.2e-3);
  EXPECT_NEAR(param(fits[0], "rho_d", 1), 0.3, 0.3e-3);
  EXPECT_NEAR(param(fits[0], "rho_d", 2), 0.1, 0.1e-3);
}

// 5% multiplicative Gaussian noise on every stored sample (a measurement's scale): the roughness comes back within
// 0.5% (0.02% measured: 12,514 pairs average the noise away) and the generating model still ranks first.
TEST(BrdfFit, WithFivePercentNoiseTheRoughnessIsWithinHalfAPercent) {
  const std::string path =
      merlFileOf(material("cooktorrance", "rho_d=0.1,rho_s=0.9,m=0.25,eta=1.5"), "noisy.binary", 0.05);
  const std::vector<FitResult> fits = fitModels(merlFitTarget(path), options({"cooktorrance", "ward"}));
  EXPECT_EQ(fits[0].model, "cooktorrance");
  EXPECT_NEAR(param(fits[0], "m"), 0.25, 0.25 * 0.005);
  std::printf("5%% noise: m = %.5f (0.25), relative error %.4f\n", param(fits[0], "m"), fits[0].relativeError);
}

TEST(BrdfFit, AMaterialTargetIsFittedAnisotropically) {
  const FitTarget target = loadFitTarget("ward:rho_d=0.1,rho_s=0.5,alpha_x=0.1,alpha_y=0.3");
  EXPECT_FALSE(target.isotropic);
  const std::vector<FitResult> fits = fitModels(target, options({"ward"}));
  EXPECT_NEAR(param(fits[0], "alpha_x"), 0.1, 1e-4);
  EXPECT_NEAR(param(fits[0], "alpha_y"), 0.3, 3e-4);
}

TEST(BrdfFit, TheSameSeedGivesTheSameFits) {
  const FitTarget target = loadFitTarget("gltf_pbr:base_color=0.7/0.5/0.2,roughness=0.4,metallic=0.3");
  FitOptions o = options({"ward", "blinnphong"}, 3);
  o.seed = 11;
  o.threads = 2;
  const std::vector<FitResult> a = fitModels(target, o);
  const std::vector<FitResult> b = fitModels(target, o);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].model, b[i].model);
    EXPECT_EQ(a[i].error, b[i].error);
    EXPECT_EQ(fitParamList(a[i]), fitParamList(b[i]));
  }
}

// A fit that names no start count gives each model its registry's: Lafortune's `fit: starts 16` (its flat valleys,
// docs/fitting.md), and SGD's `fit: start` point (Bagher's median shadowing) is one of its starts.
TEST(BrdfFit, TheRegistrysStartCountAndStartAreAFitsDefaults) {
  const FitTarget target = loadFitTarget("lambert:rho_d=0.5");
  FitOptions o = options({"lafortune"}, 0);
  EXPECT_EQ(fitModels(target, o)[0].starts, 16);
  o.starts = 4;
  EXPECT_EQ(fitModels(target, o)[0].starts, 4) << "a count the fit names is every model's";

  const ModelInfo& sgd = *findModel("sgd");
  ASSERT_FALSE(sgd.fitStart.empty());
  const fitting::ModelPlan plan = fitting::planOf(sgd, true);
  ASSERT_EQ(plan.declaredStart.size(), plan.variables.size());
  std::mt19937_64 random(1);
  const std::vector<fitting::Scored> starts =
      fitting::searchBasins(fitting::coarseTarget(target), plan, FitMetric::kCosine, 64, 4, random);
  bool found = false;
  for (const fitting::Scored& start : starts) {
    bool same = true;
    for (int j : plan.nonlinear) same &= start.x[std::size_t(j)] == plan.declaredStart[std::size_t(j)];
    found |= same;
  }
  EXPECT_TRUE(found) << "the declared start is among the search's " << starts.size();
  reference::Material at = plan.base;
  fitting::applyVariables(plan.variables, plan.declaredStart.data(), at);
  for (const auto& [name, value] : sgd.fitStart) {
    const ParamInfo* param = findParam(sgd, name);
    ASSERT_NE(param, nullptr) << name;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at.params[param->slot + c], value, 1e-9 * value) << name << " " << c;
  }
}

// openpbr is fitted only when named (`fit: by name`), and then only in what its `fit: free` line frees: every other
// parameter stays at its default.
TEST(BrdfFit, OpenPbrIsFittedByNameInTheParametersItsRegistryFrees) {
  const std::vector<std::string> defaults = fittableModels(), all = fittableModels(true);
  EXPECT_EQ(std::count(defaults.begin(), defaults.end(), "openpbr"), 0);
  EXPECT_EQ(std::count(all.begin(), all.end(), "openpbr"), 1);
  EXPECT_EQ(all.size(), defaults.size() + 1);
  const ModelInfo& openpbr = *findModel("openpbr");
  ASSERT_FALSE(openpbr.fitFree.empty());
  const fitting::ModelPlan plan = fitting::planOf(openpbr, true);
  std::size_t expected = 0;
  for (std::string_view name : openpbr.fitFree) expected += findParam(openpbr, name)->rgb ? 3 : 1;
  EXPECT_EQ(plan.variables.size(), expected);
  for (const fitting::Variable& v : plan.variables) {
    bool freed = false;
    for (std::string_view name : openpbr.fitFree) {
      const ParamInfo* p = findParam(openpbr, name);
      freed |= v.slots.front() >= p->slot && v.slots.front() < p->slot + (p->rgb ? 3u : 1u);
    }
    EXPECT_TRUE(freed) << "slot " << v.slots.front();
  }
}

TEST(BrdfFit, BadTargetsAreRefusedNamingTheFileAndLine) {
  const std::string csv = scratch("samples.csv");
  std::ofstream(csv) << "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n0 ,0,1,0,0,1,0.1,0.1,0.1\n0,0,1,0,0,1,nan,0,0\n";
  EXPECT_NE(errorOf([&] { csvFitTarget(csv); }).find("samples.csv:3"), std::string::npos);
  std::ofstream(csv) << "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n0,0,-1,0,0,1,0.1,0.1,0.1\n";
  EXPECT_NE(errorOf([&] { csvFitTarget(csv); }).find("above the surface"), std::string::npos);
  std::ofstream(csv) << "a,b\n";
  EXPECT_NE(errorOf([&] { csvFitTarget(csv); }).find("expected the header"), std::string::npos);
  std::ofstream(csv) << "";
  EXPECT_NE(errorOf([&] { csvFitTarget(csv); }).find("empty"), std::string::npos);
  EXPECT_NE(errorOf([&] { loadFitTarget("glass"); }).find("delta"), std::string::npos);
  EXPECT_NE(errorOf([&] { loadFitTarget("nonsense"); }).find("neither"), std::string::npos);
  EXPECT_NE(errorOf([&] { loadFitTarget(scratch("missing.binary")); }).find("missing.binary"), std::string::npos);
  EXPECT_NE(errorOf([&] { loadFitTarget(fs::temp_directory_path().string() + "/"); }).find("neither"), std::string::npos);
  const FitTarget target = loadFitTarget("lambert");
  EXPECT_NE(errorOf([&] { fitModels(target, options({"glass"})); }).find("is not a model that can be fitted"), std::string::npos);
  EXPECT_NE(errorOf([&] { fitModels(target, options({"ward", "ward"})); }).find("twice"), std::string::npos);
  // A million samples is the cap (each thread's Jacobian has 3 rows per sample): the next one is refused, naming
  // its line, before anything is fitted.
  std::string many = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n";
  const std::string row = "0,0,1,0,0,1,0.1,0.1,0.1\n";
  many.reserve(many.size() + row.size() * 1000001);
  for (int i = 0; i < 1000000; ++i) many += row;
  EXPECT_EQ(parseFitCsv(many, "many.csv").pairs.size(), 1000000u);
  many += row;
  const std::string refused = errorOf([&] { parseFitCsv(many, "many.csv"); });
  EXPECT_NE(refused.find("many.csv:1000002: more than 1000000 samples"), std::string::npos) << refused;
}

}  // namespace
}  // namespace raylab::test
