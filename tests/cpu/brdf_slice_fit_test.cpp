// Fitting MERL phi_d = 90 slices and weighted CSV targets (engine/fit, docs/fitting.md "Measured slices"): the bins'
// weights sum to the measure, a slice written from a known model is fitted back, x and y are tied when they should
// be, bad slices and weights are refused naming the file and what is wrong, and a fit that leaves out a term the
// data shows, or a parameter the data cannot see, says so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include "brdf_params/material_params.h"
#include "fit/fit.h"
#include "fit/fit_plan.h"
#include "fit_test_support.h"
#include "fit/merl_slice.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

std::string scratch(const std::string& name) { return scratchFile("slice_fit_test", name); }

gpu::MaterialRecord material(const std::string& model, const std::string& params) { return materialOf(model, params); }

// The slice of `record`: f at each bin's `bin` position on the plane phi_d = 90 degrees.
MerlSlice sliceOf(const gpu::MaterialRecord& record, SliceBin bin = SliceBin::kCentre) {
  const reference::Material m = reference::fromRecord(record);
  MerlSlice slice;
  slice.values.resize(kSliceBytes / sizeof(float));
  for (int d = 0; d < kSliceThetaD; ++d) {
    for (int h = 0; h < kSliceThetaH; ++h) {
      glm::dvec3 wi, wo;
      merlDirections(sliceThetaH(h, bin), sliceThetaD(d, bin), 0.5 * kPi, &wi, &wo);
      const glm::dvec3 f = reference::eval(m, wi, wo);
      for (int c = 0; c < 3; ++c) slice.values[(std::size_t(d) * kSliceThetaH + h) * 3 + c] = float(f[c]);
    }
  }
  return slice;
}

std::string write(const std::string& name, const std::string& bytes) {
  const std::string path = scratch(name);
  writeFileAtomically(path, bytes);
  return path;
}

double param(const FitResult& fit, const std::string& name, int channel = 0) {
  return getParam(fit.record, name)[channel];
}

FitOptions options(std::vector<std::string> models) {
  FitOptions o;
  o.models = std::move(models);
  return o;
}

// Error's message and exit code, or empty and 0.
std::pair<std::string, int> errorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& error) {
    return {error.what(), error.exitCode()};
  }
  return {"", 0};
}

TEST(SliceFit, TheBinsWeightsSumToTheMeasure) {
  // int_0^{pi/2} sin theta_h dtheta_h * int_0^{pi/2} 4 cos theta_d sin theta_d dtheta_d = 1 * 2.
  double sum = 0.0;
  for (int d = 0; d < kSliceThetaD; ++d) {
    for (int h = 0; h < kSliceThetaH; ++h) {
      const double w = sliceBinMeasure(h, d);
      EXPECT_GT(w, 0.0);
      sum += w;
    }
  }
  EXPECT_NEAR(sum, 2.0, 1e-12);
  // A bin near the highlight is narrow along theta_h: MERL's square-root axis crowds samples there, and the weight
  // hands them back their share.
  EXPECT_LT(sliceBinMeasure(0, 45), 1e-3 * sliceBinMeasure(89, 45));
  // The target's weights are the bins' measures, renormalised over the pairs it keeps.
  const std::string path =
      write("lambert.slice", encodeMerlSlice(sliceOf(material("lambert", "rho_d=0.5"))));
  const FitTarget target = sliceFitTarget(path);
  double total = 0.0;
  for (const FitPair& pair : target.pairs) total += pair.weight;
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_TRUE(target.isotropic);
  EXPECT_LT(target.pairs.size(), std::size_t(kSliceThetaH * kSliceThetaD)) << "grazing pairs are left out";
}

TEST(SliceFit, ASliceOfAKnownModelIsFittedBackWithinOnePerMille) {
  const gpu::MaterialRecord truth = material("cooktorrance", "rho_d=0.2/0.3/0.1,rho_s=0.6/0.5/0.4,m=0.15,eta=1.6");
  for (SliceBin bin : {SliceBin::kCentre, SliceBin::kStart}) {
    const std::string path = write("ct.slice", encodeMerlSlice(sliceOf(truth, bin)));
    const std::vector<FitResult> fits =
        fitModels(sliceFitTarget(path, bin), options({"ward", "cooktorrance", "gltf_pbr"}));
    ASSERT_EQ(fits[0].model, "cooktorrance");
    EXPECT_LT(fits[0].relativeError, 1e-5);
    for (const ParamInfo& p : modelInfo(truth.model).params) {
      for (int c = 0; c < (p.rgb ? 3 : 1); ++c) {
        const double want = truth.params[p.slot + c];
        EXPECT_NEAR(param(fits[0], std::string(p.name), c), want, 1e-3 * want) << p.name << " " << c;
      }
    }
    EXPECT_TRUE(fits[0].warnings.empty()) << fits[0].warnings.front();
  }
}

TEST(SliceFit, IsotropicTiesXAndYForAnyTarget) {
  const std::string path =
      write("ward.slice", encodeMerlSlice(sliceOf(material("ward", "rho_d=0.1,rho_s=0.3,alpha_x=0.1,alpha_y=0.1"))));
  const std::vector<FitResult> slice = fitModels(sliceFitTarget(path), options({"ward", "ashikhmin_shirley"}));
  for (const FitResult& fit : slice) {
    if (fit.model == "ward") {
      EXPECT_EQ(param(fit, "alpha_x"), param(fit, "alpha_y"));
    } else {
      EXPECT_EQ(param(fit, "nu"), param(fit, "nv"));
    }
  }
  // An anisotropic material target: free by default, tied when asked.
  const FitTarget target = loadFitTarget("ward:rho_d=0.1,rho_s=0.5,alpha_x=0.1,alpha_y=0.3");
  FitOptions tied = options({"ward"});
  tied.isotropic = true;
  const FitResult isotropic = fitModels(target, tied)[0];
  EXPECT_EQ(param(isotropic, "alpha_x"), param(isotropic, "alpha_y"));
  const FitResult free = fitModels(target, options({"ward"}))[0];
  EXPECT_NEAR(param(free, "alpha_y") / param(free, "alpha_x"), 3.0, 3e-3);
  // And a slice fitted apart on request: the slice cannot see anisotropy, but the tie is the user's to drop.
  FitOptions apart = options({"ward"});
  apart.isotropic = false;
  EXPECT_NO_THROW(fitModels(sliceFitTarget(path), apart));
}

TEST(SliceFit, BadSlicesAreRefusedNamingTheFileAndTheValue) {
  const std::string good = encodeMerlSlice(sliceOf(material("lambert", "rho_d=0.5")));
  const auto refused = [&](const std::string& name, const std::string& bytes, const std::string& says) {
    const std::string path = write(name, bytes);
    const auto [message, code] = errorOf([&] { loadFitTarget(path); });
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
    EXPECT_EQ(code, kExitUsage) << message;
  };
  refused("short.slice", good.substr(0, 1000), "holds 1000 bytes");
  refused("long.slice", good + "x", "bytes");
  const auto with = [&](std::size_t index, float value) {
    std::string bytes = good;
    std::memcpy(bytes.data() + index * sizeof(float), &value, sizeof value);
    return bytes;
  };
  refused("nan.slice", with((7 * 90 + 5) * 3 + 1, NAN), "theta_d row 7, theta_h column 5, green is NaN");
  refused("inf.slice", with(2, INFINITY), "blue is inf");
  refused("negative.slice", with(3, -0.5f), "negative");
  refused("huge.slice", with(4, 1e30f), "theta_h column 1, green is above 1e+20");
  refused("zeros.slice", std::string(kSliceBytes, '\0'), "every value is zero");
}

TEST(SliceFit, ACsvWeightColumnWeightsTheSamples) {
  // Samples of Lambert 0.3, and three of 10 weighted 0: the fit sees only the others.
  std::string text = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b,weight\n";
  for (int i = 0; i < 40; ++i) {
    const double a = 0.1 * i, b = 0.17 * i;
    char row[256];
    const double f = (i % 10 < 3) ? 10.0 : 0.3 / kPi;
    std::snprintf(row, sizeof row, "%.9f,%.9f,0.8,%.9f,%.9f,0.7,%.9g,%.9g,%.9g,%d\n", 0.5 * std::cos(a),
                  0.5 * std::sin(a), 0.6 * std::cos(b), 0.6 * std::sin(b), f, f, f, (i % 10 < 3) ? 0 : 1);
    text += row;
  }
  const FitResult lambert = fitModels(csvFitTarget(write("weighted.csv", text)), options({"lambert"}))[0];
  EXPECT_NEAR(param(lambert, "rho_d"), 0.3, 1e-6);
  EXPECT_LT(lambert.relativeError, 1e-6);

  const auto refused = [&](const std::string& body, const std::string& says) {
    const std::string path = write("bad_weight.csv", "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b,weight\n" + body);
    const auto [message, code] = errorOf([&] { csvFitTarget(path); });
    EXPECT_NE(message.find(says), std::string::npos) << message;
    EXPECT_EQ(code, kExitUsage);
  };
  refused("0,0,1,0,0,1,0.1,0.1,0.1,-1\n", "bad_weight.csv:2: the weight is negative");
  refused("0,0,1,0,0,1,0.1,0.1,0.1,nan\n", "bad_weight.csv:2: field 10 'nan' is not a finite number");
  refused("0,0,1,0,0,1,0.1,0.1,0.1,0\n0,0,1,0,0,1,0.1,0.1,0.1,0\n", "the weights sum to zero");
  refused("0,0,1,0,0,1,0.1,0.1,0.1,1,7\n", "more than 10 fields");
  refused("0,0,1,0,0,1,1e38,0.1,0.1,1\n", "bad_weight.csv:2: f above 1e+20");
  refused("0,0,1,0,0,1,0.1,0.1,0.1,1e308\n0,0,1,0,0,1,0.1,0.1,0.1,1e308\n", "more than a double holds");
  // Nine columns, ten fields: named as such, not as a bad number.
  const std::string nine = write("nine.csv", "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n0,0,1,0,0,1,0.1,0.1,0.1,1\n");
  EXPECT_NE(errorOf([&] { csvFitTarget(nine); }).first.find("more than 9 fields"), std::string::npos);
  // A byte order mark before the header is skipped.
  const std::string bom = write("bom.csv", "\xEF\xBB\xBFwi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n0,0,1,0,0,1,0.1,0.1,0.1\n");
  EXPECT_EQ(csvFitTarget(bom).pairs.size(), 1u);
}

TEST(SliceFit, AFitThatLeavesOutTheDiffuseFloorWarns) {
  // A plastic: a clear diffuse floor under a highlight. A conductor has no diffuse term: its fit must say so.
  const std::string path = write(
      "plastic.slice", encodeMerlSlice(sliceOf(material("cooktorrance", "rho_d=0.1/0.2/0.5,rho_s=0.5,m=0.05,eta=1.5"))));
  const std::vector<FitResult> fits = fitModels(sliceFitTarget(path), options({"ggx_conductor", "cooktorrance"}));
  for (const FitResult& fit : fits) {
    bool warned = false;
    for (const std::string& w : fit.warnings) warned |= w.find("away from the highlight") != std::string::npos;
    EXPECT_EQ(warned, fit.model == "ggx_conductor") << fit.model;
  }
}

TEST(SliceFit, ParametersTheDataCannotSeeAreReportedAndTiesPreferTheSimplerModel) {
  // Pure Lambert: Cook-Torrance's highlight fits to nothing, and its roughness and index are then unconstrained.
  const FitTarget target = loadFitTarget("lambert:rho_d=0.4/0.5/0.6");
  const std::vector<FitResult> fits = fitModels(target, options({"oren_nayar", "cooktorrance", "lambert"}));
  EXPECT_EQ(fits[0].model, "lambert") << "a tie goes to the model with fewer parameters";
  for (const FitResult& fit : fits) {
    if (fit.model != "cooktorrance") continue;
    EXPECT_LT(param(fit, "rho_s"), 1e-6);
    std::string all;
    for (const std::string& w : fit.warnings) all += w + "\n";
    EXPECT_NE(all.find("m is not constrained"), std::string::npos) << all;
    EXPECT_NE(all.find("eta is not constrained"), std::string::npos) << all;
  }
}

// The names of a plan's variables (an RGB parameter's channel as name[c]).
std::vector<std::string> namesOf(const fitting::ModelPlan& plan, const std::vector<int>& variables) {
  std::vector<std::string> names;
  for (int j : variables) {
    for (const ParamInfo& p : plan.model->params) {
      const std::uint32_t slot = plan.variables[std::size_t(j)].slots.front();
      if (slot < p.slot || slot >= p.slot + (p.rgb ? 3u : 1u)) continue;
      names.push_back(std::string(p.name) + (p.rgb ? "[" + std::to_string(slot - p.slot) + "]" : ""));
    }
  }
  return names;
}

TEST(SliceFit, ThePlanFindsEachLobesOwnParametersAndTheChannelsEachVariableMoves) {
  // Lafortune: each lobe's axis and exponent matter only through its weight (the x and y of the axis tied).
  const fitting::ModelPlan lafortune = fitting::planOf(*findModel("lafortune"), true);
  ASSERT_EQ(lafortune.lobes.size(), 2u);
  EXPECT_EQ(namesOf(lafortune, lafortune.lobes[0].variables), (std::vector<std::string>{"cx", "cz", "n"}));
  EXPECT_EQ(namesOf(lafortune, lafortune.lobes[1].variables), (std::vector<std::string>{"cxy2", "cz2", "n2"}));
  // The conductor: the roughness moves every channel; each channel of eta, k and rho_s only its own, so the
  // Jacobian's 9 colour columns take 3 evaluations.
  const fitting::ModelPlan conductor = fitting::planOf(*findModel("ggx_conductor"), true);
  EXPECT_EQ(conductor.diffGroups.size(), 4u);
  for (const std::vector<int>& group : conductor.diffGroups) {
    const std::vector<std::string> names = namesOf(conductor, group);
    if (names.size() == 1) {
      EXPECT_EQ(names[0], "alpha_x");
      continue;
    }
    ASSERT_EQ(names.size(), 3u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(conductor.variables[std::size_t(group[std::size_t(c)])].channel, c);
  }
  // SGD's shadowing reaches over decades from 0: it is searched as log(1 + value / scale), 0 still in range.
  const fitting::ModelPlan sgd = fitting::planOf(*findModel("sgd"), true);
  int wide = 0;
  for (const fitting::Variable& v : sgd.variables) {
    if (v.wideScale <= 0.0) continue;
    ++wide;
    reference::Material m = sgd.base;
    const double low = v.lo;
    fitting::applyVariables({v}, &low, m);
    EXPECT_EQ(m.params[v.slots[0]], 0.0);
  }
  EXPECT_EQ(wide, 6) << "lambda and c, each channel";
}

TEST(SliceFit, AnUnusedLobeIsGrownAgain) {
  // Two forward lobes, a sharp one and a broad one, over a diffuse floor: the default fit must find both.
  const gpu::MaterialRecord truth =
      material("lafortune", "rho_d=0.3/0.28/0.25,rho_s=0.07/0.05/0.04,cx=-0.6,cy=-0.6,cz=0.6,n=5000,"
                            "rho_s2=0.02/0.015/0.012,cxy2=-0.6,cz2=0.6,n2=300");
  const std::string path = write("lafortune.slice", encodeMerlSlice(sliceOf(truth)));
  FitOptions o = options({"lafortune"});
  o.metric = FitMetric::kLog;
  const std::vector<FitResult> fits = fitModels(sliceFitTarget(path), o);
  EXPECT_LT(fits[0].relativeError, 1e-3) << fitParamList(fits[0]);
}

TEST(SliceFit, AMeasuredMaterialIsAMaterialEvenWhenItsFileEndsInBinary) {
  const auto [message, code] = errorOf([&] { loadFitTarget("measured:file=" + scratch("absent.binary")); });
  EXPECT_EQ(message.find("neither"), std::string::npos) << message;
  EXPECT_NE(message.find("absent.binary"), std::string::npos) << message;
}

}  // namespace
}  // namespace raylab::test
