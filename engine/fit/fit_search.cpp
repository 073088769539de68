#include "fit/fit_search.h"

#include <algorithm>
#include <cmath>

namespace raylab::fitting {

namespace {

// Two search points closer than this in every nonlinear variable (as a fraction of its range) are one basin.
constexpr double kDistinctStarts = 0.02;

// Solves one block of linear groups of `plan` at `x` (the other variables held) in each channel: minimise
// sum w cos^2 (t - h - sum_k a_k g_k)^2 (times 1 / (1 + t cos)^2 for the log metric, its first-order weight)
// within the parameters' ranges; writes the amounts into x and returns the metric's cost of the result.
double solveBlock(const std::vector<const FitPair*>& pairs, const ModelPlan& plan, const std::vector<int>& block,
                  FitMetric metric, std::vector<double>& x) {
  const std::size_t groups = block.size();
  const auto variable = [&](std::size_t k, int c) {
    return std::size_t(plan.linear[std::size_t(block[k])].variables[std::size_t(c)]);
  };
  for (std::size_t k = 0; k < groups; ++k) {
    for (int c = 0; c < 3; ++c) x[variable(k, c)] = 0.0;
  }
  reference::Material zero = plan.base;
  applyVariables(plan.variables, x.data(), zero);
  std::vector<glm::dvec3> h(pairs.size());
  std::vector<std::vector<glm::dvec3>> g(groups, std::vector<glm::dvec3>(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i) h[i] = reference::eval(zero, pairs[i]->wi, pairs[i]->wo);
  for (std::size_t k = 0; k < groups; ++k) {
    reference::Material unit = zero;
    for (int c = 0; c < 3; ++c) {
      for (std::uint32_t slot : plan.variables[variable(k, c)].slots) unit.params[slot] = 1.0;
    }
    for (std::size_t i = 0; i < pairs.size(); ++i) g[k][i] = reference::eval(unit, pairs[i]->wi, pairs[i]->wo) - h[i];
  }
  for (int c = 0; c < 3; ++c) {
    std::vector<double> A(groups * groups, 0.0), b(groups, 0.0), lo(groups), hi(groups);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const FitPair& pair = *pairs[i];
      double w = pair.weight * pair.wi.z * pair.wi.z;
      if (metric == FitMetric::kLog) w /= (1.0 + pair.f[c] * pair.wi.z) * (1.0 + pair.f[c] * pair.wi.z);
      if (!std::isfinite(h[i][c])) continue;
      for (std::size_t k = 0; k < groups; ++k) {
        const double gk = g[k][i][c];
        if (!std::isfinite(gk)) continue;
        b[k] += w * gk * (pair.f[c] - h[i][c]);
        for (std::size_t l = 0; l < groups; ++l) {
          if (std::isfinite(g[l][i][c])) A[k * groups + l] += w * gk * g[l][i][c];
        }
      }
    }
    for (std::size_t k = 0; k < groups; ++k) {
      lo[k] = plan.variables[variable(k, c)].lo;
      hi[k] = plan.variables[variable(k, c)].hi;
    }
    const std::vector<double> a = boxLeastSquares(A, b, lo, hi);
    for (std::size_t k = 0; k < groups; ++k) x[variable(k, c)] = a[k];
  }
  double cost = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    glm::dvec3 f = h[i];
    for (std::size_t k = 0; k < groups; ++k) {
      for (int c = 0; c < 3; ++c) f[c] += x[variable(k, c)] * g[k][i][c];
    }
    for (int c = 0; c < 3; ++c) {
      const double r = residual(metric, pairs[i]->f[c], f[c], pairs[i]->wi.z);
      cost += pairs[i]->weight * r * r;
    }
  }
  return std::isfinite(cost) ? cost : INFINITY;
}

// The metric's cost of x on `pairs`, with its linear blocks solved by least squares in turn (`cycles` times when
// there are several) and written into x.
double solvedCost(const std::vector<const FitPair*>& pairs, const ModelPlan& plan, FitMetric metric, int cycles,
                  std::vector<double>& x) {
  if (plan.blocks.empty()) {
    reference::Material material = plan.base;
    applyVariables(plan.variables, x.data(), material);
    double cost = 0.0;
    for (const FitPair* pair : pairs) {
      const glm::dvec3 f = reference::eval(material, pair->wi, pair->wo);
      for (int c = 0; c < 3; ++c) {
        const double r = residual(metric, pair->f[c], f[c], pair->wi.z);
        cost += pair->weight * r * r;
      }
    }
    return std::isfinite(cost) ? cost : INFINITY;
  }
  double cost = INFINITY;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    for (const std::vector<int>& block : plan.blocks) cost = solveBlock(pairs, plan, block, metric, x);
  }
  return cost;
}

}  // namespace

// min over lo <= a <= hi of a'Aa - 2 b'a (A positive semi-definite, n <= 4): the optimum of a convex quadratic
// over a box lies on the face where its free variables solve their equations, so every face is tried.
std::vector<double> boxLeastSquares(const std::vector<double>& A, const std::vector<double>& b,
                                    const std::vector<double>& lo, const std::vector<double>& hi) {
  const std::size_t n = b.size();
  std::vector<double> best(n), a(n);
  double bestCost = INFINITY;
  std::size_t faces = 1;
  for (std::size_t i = 0; i < n; ++i) faces *= 3;
  for (std::size_t face = 0; face < faces; ++face) {
    std::vector<int> state(n);  // 0 free, 1 at lo, 2 at hi
    std::size_t code = face;
    std::vector<std::size_t> free;
    for (std::size_t i = 0; i < n; ++i) {
      state[i] = int(code % 3);
      code /= 3;
      if (state[i] == 0) free.push_back(i);
      a[i] = state[i] == 1 ? lo[i] : hi[i];
    }
    if (!free.empty()) {
      // The free variables' normal equations with the bound ones moved to the right: Gaussian elimination with
      // partial pivoting on at most 4 unknowns; a singular system (a direction f does not depend on) skips the face.
      const std::size_t m = free.size();
      std::vector<double> M(m * (m + 1));
      for (std::size_t r = 0; r < m; ++r) {
        double rhs = b[free[r]];
        for (std::size_t j = 0; j < n; ++j) {
          if (state[j] != 0) rhs -= A[free[r] * n + j] * a[j];
        }
        for (std::size_t c = 0; c < m; ++c) M[r * (m + 1) + c] = A[free[r] * n + free[c]];
        M[r * (m + 1) + m] = rhs;
      }
      bool singular = false;
      for (std::size_t c = 0; c < m && !singular; ++c) {
        std::size_t pivot = c;
        for (std::size_t r = c + 1; r < m; ++r) {
          if (std::abs(M[r * (m + 1) + c]) > std::abs(M[pivot * (m + 1) + c])) pivot = r;
        }
        const double scale = std::abs(A[free[c] * n + free[c]]) + 1e-300;
        if (!(std::abs(M[pivot * (m + 1) + c]) > 1e-12 * scale)) {
          singular = true;
          break;
        }
        for (std::size_t k = 0; k <= m; ++k) std::swap(M[c * (m + 1) + k], M[pivot * (m + 1) + k]);
        for (std::size_t r = 0; r < m; ++r) {
          if (r == c) continue;
          const double factor = M[r * (m + 1) + c] / M[c * (m + 1) + c];
          for (std::size_t k = c; k <= m; ++k) M[r * (m + 1) + k] -= factor * M[c * (m + 1) + k];
        }
      }
      if (singular) continue;
      bool inside = true;
      for (std::size_t r = 0; r < m; ++r) {
        const double value = M[r * (m + 1) + m] / M[r * (m + 1) + r];
        inside &= value >= lo[free[r]] && value <= hi[free[r]];
        a[free[r]] = value;
      }
      if (!inside) continue;
    }
    double cost = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      cost -= 2.0 * b[i] * a[i];
      for (std::size_t j = 0; j < n; ++j) cost += a[i] * A[i * n + j] * a[j];
    }
    if (cost < bestCost) {
      bestCost = cost;
      best = a;
    }
  }
  return best;
}

std::vector<double> channelSearch(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric,
                                  const std::vector<double>& x) {
  std::vector<const FitPair*> pairs;
  for (const FitPair& pair : coarse.pairs) pairs.push_back(&pair);
  // A grid of about kChannelPoints points per channel over the nonlinear colours' values, each axis drawn densest near
  // its lower bound as in the grey search (u^2): 12 x 12 for a conductor's eta and k.
  constexpr int kChannelPoints = 144;
  const int axes = int(plan.nonlinearColours.size());
  const int perAxis = std::max(2, int(std::lround(std::pow(double(kChannelPoints), 1.0 / axes))));
  int points = 1;
  for (int a = 0; a < axes; ++a) points *= perAxis;
  std::vector<double> repaired = x;
  for (int c = 0; c < 3; ++c) {
    double bestCost = INFINITY;
    std::vector<double> bestValues;
    for (int point = 0; point < points; ++point) {
      std::vector<double> trial = repaired;
      std::vector<double> values;
      int code = point;
      for (const std::array<int, 3>& colour : plan.nonlinearColours) {
        const Variable& v = plan.variables[std::size_t(colour[std::size_t(c)])];
        const double u = ((code % perAxis) + 0.5) / perAxis;
        code /= perAxis;
        values.push_back(v.lo + (v.hi - v.lo) * u * u);
        trial[std::size_t(colour[std::size_t(c)])] = values.back();
      }
      // The other channels are held, so the cost ranks this channel's points (f's channels are separate).
      const double cost = solvedCost(pairs, plan, metric, 1, trial);
      if (cost < bestCost) {
        bestCost = cost;
        bestValues = values;
      }
    }
    for (std::size_t a = 0; a < bestValues.size(); ++a) {
      repaired[std::size_t(plan.nonlinearColours[a][std::size_t(c)])] = bestValues[a];
    }
  }
  solvedCost(pairs, plan, metric, 1, repaired);
  return repaired;
}

std::vector<double> lobeSearch(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric,
                               const std::vector<double>& x, int points, std::mt19937_64& random) {
  // Below this share of the model's reflected light (sum of w cos |f| over the pairs and channels) a lobe is unused.
  constexpr double kUnusedShare = 1e-3;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<const FitPair*> pairs;
  for (const FitPair& pair : coarse.pairs) pairs.push_back(&pair);
  const int cycles = plan.blocks.size() > 1 ? 3 : 1;
  std::vector<double> current = x;
  bool regrown = false;
  for (const ModelPlan::Lobe& lobe : plan.lobes) {
    reference::Material with = plan.base, without = plan.base;
    applyVariables(plan.variables, current.data(), with);
    std::vector<double> zeroed = current;
    for (int j : plan.linear[std::size_t(lobe.group)].variables) zeroed[std::size_t(j)] = 0.0;
    applyVariables(plan.variables, zeroed.data(), without);
    double share = 0.0, total = 0.0;
    for (const FitPair* pair : pairs) {
      const glm::dvec3 f = reference::eval(with, pair->wi, pair->wo);
      const glm::dvec3 g = reference::eval(without, pair->wi, pair->wo);
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(f[c]) || !std::isfinite(g[c])) continue;
        share += pair->weight * pair->wi.z * std::abs(f[c] - g[c]);
        total += pair->weight * pair->wi.z * std::abs(f[c]);
      }
    }
    if (!(share < kUnusedShare * total)) continue;
    // A Latin hypercube of the lobe's own variables, as the search's (searchBasins).
    const std::size_t n = lobe.variables.size();
    std::vector<std::vector<int>> strata(n);
    for (auto& s : strata) {
      for (int p = 0; p < points; ++p) s.push_back(p);
      std::shuffle(s.begin(), s.end(), random);
    }
    double bestCost = INFINITY;
    std::vector<double> best;
    for (int p = 0; p < points; ++p) {
      std::vector<double> trial = current;
      for (std::size_t j = 0; j < n; ++j) {
        const Variable& v = plan.variables[std::size_t(lobe.variables[j])];
        const double u = (strata[j][std::size_t(p)] + uniform(random)) / points;
        trial[std::size_t(lobe.variables[j])] = v.lo + (v.hi - v.lo) * u;
      }
      const double cost = solvedCost(pairs, plan, metric, cycles, trial);
      if (cost < bestCost) {
        bestCost = cost;
        best = std::move(trial);
      }
    }
    if (!best.empty()) {
      current = std::move(best);
      regrown = true;
    }
  }
  return regrown ? current : std::vector<double>{};
}

// The pairs the search and the first LM solves use: every k-th of the target's, about kSearchPairs.
FitTarget coarseTarget(const FitTarget& target) {
  FitTarget coarse;
  coarse.name = target.name;
  coarse.isotropic = target.isotropic;
  const std::size_t stride = std::max<std::size_t>(1, target.pairs.size() / kSearchPairs);
  for (std::size_t i = 0; i < target.pairs.size(); i += stride) coarse.pairs.push_back(target.pairs[i]);
  return coarse;
}

// The search of FitOptions: `points` points of the nonlinear variables (the defaults first, then a Latin hypercube
// of the box), each with its linear blocks solved by least squares in turn, scored by the metric on the coarse
// pairs; the best `starts` distinct points, best first.
std::vector<Scored> searchBasins(const FitTarget& coarse, const ModelPlan& plan, FitMetric metric, int points,
                                 int starts, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<const FitPair*> pairs;
  for (const FitPair& pair : coarse.pairs) pairs.push_back(&pair);
  const std::size_t n = plan.variables.size();

  // A Latin hypercube: each variable's range cut into `count` strata, one point in each, the strata shuffled per
  // variable (a linear variable's value starts the alternation between blocks). A grey hypercube gives the channels
  // of each nonlinear colour one value: a conductor's eta and k per channel make a 7-dimensional box in which 256
  // points rarely land every channel in its basin, while the best fits of most materials are near grey.
  std::vector<std::vector<double>> xs;
  std::vector<double> defaults(n);
  for (std::size_t i = 0; i < n; ++i) defaults[i] = plan.variables[i].start;
  xs.push_back(defaults);
  const auto hypercube = [&](int count, bool grey) {
    std::vector<std::vector<int>> strata(n);
    for (auto& s : strata) {
      for (int p = 0; p < count; ++p) s.push_back(p);
      std::shuffle(s.begin(), s.end(), random);
    }
    for (int p = 0; p < count; ++p) {
      std::vector<double> x = defaults;
      for (std::size_t j = 0; j < n; ++j) {
        const Variable& v = plan.variables[j];
        x[j] = v.lo + (v.hi - v.lo) * (strata[j][std::size_t(p)] + uniform(random)) / count;
      }
      // A grey colour is drawn densest near its lower bound (u^2), where the dielectrics' indices lie (eta 1-2 and
      // k = 0 among a conductor's eta in [0.01, 10] and k in [0, 20]): uniform draws leave a plastic's basin about
      // one point in 128.
      for (const std::array<int, 3>& colour : plan.nonlinearColours) {
        if (!grey) break;
        const Variable& v = plan.variables[std::size_t(colour[0])];
        const double u = (x[std::size_t(colour[0])] - v.lo) / (v.hi - v.lo);
        for (int c = 0; c < 3; ++c) x[std::size_t(colour[std::size_t(c)])] = v.lo + (v.hi - v.lo) * u * u;
      }
      xs.push_back(std::move(x));
    }
  };
  hypercube(points - 1, false);
  const std::size_t firstGrey = xs.size();
  if (!plan.nonlinearColours.empty()) hypercube(points / 2, true);

  std::vector<Scored> scored;
  const int cycles = plan.blocks.size() > 1 ? 3 : 1;
  for (std::size_t index = 0; index < xs.size(); ++index) {
    const double cost = solvedCost(pairs, plan, metric, cycles, xs[index]);
    scored.push_back({xs[index], cost, index >= firstGrey});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) { return a.cost < b.cost; });
  std::vector<Scored> chosen;
  const auto distinct = [&](const Scored& candidate) {
    for (const Scored& c : chosen) {
      bool near = true;
      for (int j : plan.nonlinear) {
        const Variable& v = plan.variables[std::size_t(j)];
        near &= std::abs(candidate.x[std::size_t(j)] - c.x[std::size_t(j)]) <= kDistinctStarts * (v.hi - v.lo);
      }
      if (near) return false;
    }
    return true;
  };
  // The best distinct points come from the box's hypercube alone; the grey one is added below: the grey draws crowd
  // the low indices that score well on a coarse slice of a metal, and a gold's own, non-grey basin was lost.
  // A model whose every nonlinear variable is a colour's channel (SGD's shape, Fresnel and shadowing per channel: 24
  // dimensions) starts from grey points alone, one fewer than `starts`: in its box no start lands near a basin (the
  // box's start never won on six slices, and dropping it saved a quarter of SGD's time).
  std::size_t colourChannels = 0;
  for (const std::array<int, 3>& colour : plan.nonlinearColours) colourChannels += colour.size();
  const bool allColour = !plan.nonlinear.empty() && colourChannels == plan.nonlinear.size();
  const int boxStarts = allColour ? 0 : starts;
  const int greyStarts = plan.nonlinearColours.empty() ? 0 : allColour ? std::max(1, starts - 1) : 1;
  for (const Scored& candidate : scored) {
    if (int(chosen.size()) == boxStarts) break;
    if (!candidate.grey && distinct(candidate)) chosen.push_back(candidate);
  }
  // And the best grey point: its channels start in one basin together, which Levenberg-Marquardt, moving them one
  // at a time, does not reach from a wrong one (a plastic's blue channel fitted as a perfect mirror, eta 0.01, k 20).
  int grey = 0;
  for (const Scored& candidate : scored) {
    if (grey == greyStarts) break;
    if (candidate.grey && distinct(candidate)) {
      chosen.push_back(candidate);
      ++grey;
    }
  }
  // The registry's declared start, its colours solved: a region the box's draws rarely reach and LM does not enter
  // from elsewhere (SGD's shadowing, a saddle at lambda = c = 0; docs/fitting.md).
  if (!plan.declaredStart.empty()) {
    std::vector<double> x = plan.declaredStart;
    const double cost = solvedCost(pairs, plan, metric, cycles, x);
    Scored declared{std::move(x), cost, false};
    if (distinct(declared)) chosen.push_back(std::move(declared));
  }
  // Then, unless one of the hypercube's starts has it already, the best point in the narrowest quarter of
  // the width's range (of `starts` strata): a wide lobe that fits the floor can outscore every narrow one whose other
  // parameters the search drew badly (a glossy phenolic's highlight under gltf_pbr), and Levenberg-Marquardt does
  // not grow a lobe from nothing.
  if (plan.width >= 0 && !chosen.empty()) {
    const Variable& v = plan.variables[std::size_t(plan.width)];
    const auto stratum = [&](const Scored& s) {
      const int k = std::clamp(int((s.x[std::size_t(plan.width)] - v.lo) / (v.hi - v.lo) * starts), 0, starts - 1);
      return plan.narrowIsLow ? k : starts - 1 - k;  // 0: the narrowest
    };
    int narrowest = starts;
    for (const Scored& c : chosen) {
      if (!c.grey) narrowest = std::min(narrowest, stratum(c));
    }
    for (const Scored& candidate : scored) {
      if (narrowest > 0 && !candidate.grey && stratum(candidate) == 0 && distinct(candidate)) {
        chosen.push_back(candidate);
        break;
      }
    }
  }
  return chosen;
}

}  // namespace raylab::fitting
