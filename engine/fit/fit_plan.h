// How `raylab brdf fit` sees a model (fit.h): its fitted parameters as optimisation variables (log space for
// log-scaled ones, x and y tied for an isotropic target), and which of them enter f linearly, found by evaluating
// the reference (docs/fitting.md, "How a fit finds its basin"). Internal to engine/fit.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "brdf_params/material_params.h"
#include "fit/fit.h"
#include "reference/brdf_reference.h"

namespace raylab::fitting {

// One optimisation variable: the parameter floats it sets (an RGB channel, or a slope_x tied with its slope_y),
// in log space for log-scaled parameters.
struct Variable {
  std::vector<std::uint32_t> slots;
  bool log = false;
  // > 0: a parameter from 0 over many decades (SGD's shadowing lambda in [0, 1e8] and c in [0, 1e38]), fitted as
  // t = log(1 + value / wideScale): log-like above wideScale, and 0 (no shadowing) still in range.
  double wideScale = 0.0;
  double lo = 0.0, hi = 1.0;  // in the variable's space
  double start = 0.0;         // the default
  int linearGroup = -1;       // >= 0: a channel of a parameter that enters f linearly (LinearGroup)
  int channel = -1;           // >= 0: the one channel of f the variable moves (an RGB parameter's channel)
};

// An RGB parameter whose channel c enters channel c of f linearly, f = h + a g, jointly with the model's other
// linear groups (found by evaluating, not declared: see findLinearGroups). The search solves these in closed form.
struct LinearGroup {
  std::array<int, 3> variables{};  // the channels' variables
};

struct ModelPlan {
  const ModelInfo* model = nullptr;
  std::vector<Variable> variables;
  std::vector<LinearGroup> linear;
  // The linear groups in blocks that are jointly linear; f is linear in each block with the others held (a
  // diffuse colour times 1 - a Fresnel colour: Ashikhmin-Shirley's Rd and Rs), so the search solves the blocks in
  // turn.
  std::vector<std::vector<int>> blocks;
  std::vector<int> nonlinear;  // variables in no linear group
  // RGB parameters that enter f nonlinearly (a conductor's eta and k), as their channels' variables: the search also
  // draws them grey, one value for the three channels (fit_search.cpp).
  std::vector<std::array<int, 3>> nonlinearColours;
  // The variable of the lobe's width (roughness, slope, exponent), if the model has one: the search spreads its
  // starts over its range (fit_search.cpp), so that a narrow highlight gets a start even when wide lobes score best.
  int width = -1;
  // The lobes: a linear group (a lobe's weight) and the nonlinear variables f depends on only through it (its axis,
  // width, Fresnel: nothing changes when the weight is 0), found by evaluating. A fit can end with a lobe unused,
  // its weight 0 and its shape wherever it was drawn, which Levenberg-Marquardt cannot regrow (no gradient); the
  // lobe search (fit_search.cpp) draws its shape again with the rest held.
  struct Lobe {
    int group = -1;              // into linear
    std::vector<int> variables;  // its own nonlinear variables
  };
  std::vector<Lobe> lobes;
  // The variables in groups for the Jacobian's differences: each group's variables move different single channels
  // of f, so one evaluation with all of them stepped gives each one's column (fit.cpp, BlockCost).
  std::vector<std::vector<int>> diffGroups;
  bool narrowIsLow = true;  // roughness and slopes: narrow lobes have low values; exponents: high
  // The registry's `fit: start` point in the variables' space (the defaults with its values), or empty: the search
  // keeps it as one more start (fit_search.cpp).
  std::vector<double> declaredStart;
  reference::Material base;
};

ModelPlan planOf(const ModelInfo& model, bool isotropic);
// Sets the material's parameters from the variables' values x (clamped to their ranges).
void applyVariables(const std::vector<Variable>& variables, const double* x, reference::Material& material);
// The fitted material at variables x (every other parameter at its default).
gpu::MaterialRecord recordOf(const ModelPlan& plan, const std::vector<double>& x);
// The metric's residual of one pair and channel, before its weight (fit.h, FitMetric).
double residual(FitMetric metric, double target, double model, double cosine);

}  // namespace raylab::fitting
