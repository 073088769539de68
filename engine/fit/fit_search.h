// The search of `raylab brdf fit` (fit.h, FitOptions): points of a model's nonlinear parameters, each with the
// parameters that enter f linearly solved by bounded least squares, scored on a coarse subset of the target's pairs;
// the best distinct points start Levenberg-Marquardt (docs/fitting.md, "How a fit finds its basin"). Internal to
// engine/fit.
#pragma once

#include <random>
#include <vector>

#include "fit/fit_plan.h"

namespace raylab::fitting {

// The search scores its points on about this many pairs (every k-th): enough to tell basins apart, a quarter of a
// slice's cost.
inline constexpr std::size_t kSearchPairs = 2048;

struct Scored {
  std::vector<double> x;
  double cost = INFINITY;
  bool grey = false;  // drawn with one value for each nonlinear colour's channels
};

// The pairs the search and the first LM solves use: every k-th of the target's, about kSearchPairs.
FitTarget coarseTarget(const FitTarget& target);

// `points` points of the nonlinear variables (the defaults first, then a Latin hypercube of the box), each with
// its linear blocks solved by least squares in turn, scored by the metric on `coarse`; the best `starts` distinct
// points, best first, then the grey, declared (plan.declaredStart) and narrowest-lobe starts where they apply.
std::vector<Scored> searchBasins(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric, int points,
                                 int starts, std::mt19937_64& random);

// A start that searches each channel again with the rest of `x` held (the width, the other channels): a grid over the
// channel's values of the nonlinear colours, its linear values solved at each point. Levenberg-Marquardt does not
// move one channel from a wrong basin to its neighbours' (a plastic's green fitted as a mirror: eta at its lower
// bound, k large, its specular scale near 0). For a model with nonlinear colours (plan.nonlinearColours).
std::vector<double> channelSearch(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric,
                                                 const std::vector<double>& x);

// A start with each unused lobe of `x` drawn again (plan.lobes: a lobe whose share of f on the coarse pairs is under
// 1e-3): `points` points of a Latin hypercube over the lobe's own variables with the rest held, the linear blocks
// solved at each; the best point. Empty when every lobe is in use.
std::vector<double> lobeSearch(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric,
                               const std::vector<double>& x, int points, std::mt19937_64& random);

// min over lo <= a <= hi of a'Aa - 2 b'a for A (n x n, row-major) positive semi-definite and small n.
std::vector<double> boxLeastSquares(const std::vector<double>& A, const std::vector<double>& b,
                                    const std::vector<double>& lo, const std::vector<double>& hi);

}  // namespace raylab::fitting
