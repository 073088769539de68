#include "fit/fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <functional>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <cmath>
#include <mutex>
#include <random>
#include <thread>

#include "brdf_params/material_params.h"
#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "util/error.h"
#include "util/timer.h"

namespace raylab {

namespace {

// Residual blocks of this many pairs: few enough blocks that Ceres' bookkeeping stays small.
constexpr std::size_t kPairsPerBlock = 256;
constexpr int kMaxIterations = 100;
// A start on the coarse pairs only has to reach its basin: the polish on every pair finishes it.
constexpr int kMaxCoarseIterations = 30;
// The search scores its points on about this many pairs (every k-th): enough to tell basins apart, a quarter of a
// slice's cost.
constexpr std::size_t kSearchPairs = 2048;
// Two search points closer than this in every nonlinear variable (as a fraction of its range) are one basin.
constexpr double kDistinctStarts = 0.02;

// One optimisation variable: the parameter floats it sets (an RGB channel, or a slope_x tied with its slope_y),
// in log space for log-scaled parameters.
struct Variable {
  std::vector<std::uint32_t> slots;
  bool log = false;
  double lo = 0.0, hi = 1.0;  // in the variable's space
  double start = 0.0;         // the default
  int linearGroup = -1;       // >= 0: a channel of a parameter that enters f linearly (LinearGroup)
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
  reference::Material base;
};

bool isSwitch(const ParamInfo& param) {
  // A 0/1 choice (multiscatter): kept at its default, not a continuous parameter.
  return !param.rgb && param.min == 0.0f && param.max == 1.0f && param.role.empty() &&
         param.meaning.find("0 off") != std::string_view::npos;
}

std::vector<Variable> variablesOf(const ModelInfo& model, bool isotropic) {
  std::vector<Variable> variables;
  const auto partner = [&](std::string_view role) -> const ParamInfo* {
    if (role == "slope_y") return findRole(model, "slope_x");
    if (role == "exponent_y") return findRole(model, "exponent_x");
    return nullptr;
  };
  for (const ParamInfo& param : model.params) {
    // Not fitted: a file, a 0/1 switch, a transmittance (the pairs are reflections: it changes nothing), and
    // KHR_materials_specular's strength and colour (gltf_pbr's F0 is its ior's to fit; with them it would have
    // many equal answers).
    if (isFileParam(param) || isSwitch(param) || param.role == "transmittance" || param.role == "specular_weight" ||
        param.role == "specular_tint") {
      continue;
    }
    if (isotropic) {
      if (const ParamInfo* x = partner(param.role)) {
        for (Variable& v : variables) {
          if (v.slots.front() == x->slot) v.slots.push_back(param.slot);
        }
        continue;
      }
    }
    for (int c = 0; c < (param.rgb ? 3 : 1); ++c) {
      Variable v;
      v.slots = {param.slot + std::uint32_t(c)};
      v.log = param.logScale;
      v.lo = v.log ? std::log(double(param.min)) : param.min;
      v.hi = v.log ? std::log(double(param.max)) : param.max;
      v.start = v.log ? std::log(double(param.defaultValue)) : param.defaultValue;
      variables.push_back(v);
    }
  }
  return variables;
}

void applyVariables(const std::vector<Variable>& variables, const double* x, reference::Material& material) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const Variable& v = variables[i];
    const double clamped = std::clamp(x[i], v.lo, v.hi);  // finite differences may step past a bound
    const double value = v.log ? std::exp(clamped) : clamped;
    for (std::uint32_t slot : v.slots) material.params[slot] = value;
  }
}

// Whether f is affine in the given RGB parameters (each channel in its own channel, jointly), tested at random
// points of the box and random pairs of directions: f(a) = f(0) + sum_k a_k (f(e_k) - f(0)) to 1e-9.
bool jointlyLinear(const ModelPlan& plan, const std::vector<std::array<int, 3>>& groups) {
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto direction = [&] {
    const double z = 0.15 + 0.85 * uniform(random), phi = 6.283185307179586 * uniform(random);
    const double r = std::sqrt(1.0 - z * z);
    return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
  };
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<double> x;
    for (const Variable& v : plan.variables) x.push_back(v.lo + (v.hi - v.lo) * uniform(random));
    reference::Material material = plan.base;
    applyVariables(plan.variables, x.data(), material);
    const auto with = [&](int group, double value) {
      reference::Material m = material;
      for (std::size_t k = 0; k < groups.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
          for (std::uint32_t slot : plan.variables[std::size_t(groups[k][c])].slots) {
            m.params[slot] = (int(k) == group) ? value : 0.0;
          }
        }
      }
      return m;
    };
    const reference::Material zero = with(-1, 0.0);
    std::vector<reference::Material> units;
    for (std::size_t k = 0; k < groups.size(); ++k) units.push_back(with(int(k), 1.0));
    reference::Material mixed = zero;
    std::vector<glm::dvec3> amounts;
    for (const auto& group : groups) {
      glm::dvec3 a;
      for (int c = 0; c < 3; ++c) {
        const Variable& v = plan.variables[std::size_t(group[c])];
        a[c] = v.lo + (v.hi - v.lo) * uniform(random);
        for (std::uint32_t slot : v.slots) mixed.params[slot] = a[c];
      }
      amounts.push_back(a);
    }
    for (int p = 0; p < 8; ++p) {
      const glm::dvec3 wi = direction(), wo = direction();
      const glm::dvec3 h = reference::eval(zero, wi, wo);
      glm::dvec3 predicted = h, scale = glm::abs(h);
      for (std::size_t k = 0; k < groups.size(); ++k) {
        const glm::dvec3 g = reference::eval(units[k], wi, wo) - h;
        predicted += amounts[k] * g;
        scale += glm::abs(amounts[k] * g);
      }
      const glm::dvec3 f = reference::eval(mixed, wi, wo);
      for (int c = 0; c < 3; ++c) {
        if (!(std::abs(f[c] - predicted[c]) <= 1e-9 * (scale[c] + std::abs(f[c])) + 1e-300)) return false;
      }
    }
  }
  return true;
}

ModelPlan planOf(const ModelInfo& model, bool isotropic) {
  ModelPlan plan;
  plan.model = &model;
  plan.variables = variablesOf(model, isotropic);
  plan.base = reference::fromRecord(defaultRecord(model.id));
  // Candidates: RGB parameters on a linear scale, each channel its own variable, each linear on its own; then in
  // blocks, each group joining the first block it is jointly linear with.
  std::vector<std::vector<std::array<int, 3>>> blocks;
  for (std::size_t i = 0; i + 2 < plan.variables.size(); ++i) {
    const Variable& v = plan.variables[i];
    if (v.log || v.slots.size() != 1) continue;
    const ParamInfo* param = nullptr;
    for (const ParamInfo& p : model.params) {
      if (p.rgb && p.slot == v.slots[0]) param = &p;
    }
    if (param == nullptr) continue;
    const std::array<int, 3> group{int(i), int(i + 1), int(i + 2)};
    i += 2;
    if (!jointlyLinear(plan, {group})) continue;
    bool placed = false;
    for (auto& block : blocks) {
      std::vector<std::array<int, 3>> trial = block;
      trial.push_back(group);
      if (!placed && jointlyLinear(plan, trial)) {
        block = trial;
        placed = true;
      }
    }
    if (!placed) blocks.push_back({group});
  }
  for (const auto& block : blocks) {
    plan.blocks.emplace_back();
    for (const auto& group : block) {
      for (int c = 0; c < 3; ++c) plan.variables[std::size_t(group[c])].linearGroup = int(plan.linear.size());
      plan.blocks.back().push_back(int(plan.linear.size()));
      plan.linear.push_back({group});
    }
  }
  for (std::size_t i = 0; i < plan.variables.size(); ++i) {
    if (plan.variables[i].linearGroup < 0) plan.nonlinear.push_back(int(i));
  }
  return plan;
}

double residual(FitMetric metric, double target, double model, double cosine) {
  return metric == FitMetric::kCosine ? (target - model) * cosine
                                      : std::log1p(target * cosine) - std::log1p(std::max(0.0, model) * cosine);
}

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

struct Scored {
  std::vector<double> x;
  double cost = INFINITY;
};

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

  // The Latin hypercube: each variable's range cut into points - 1 strata, one point in each, the strata shuffled
  // per variable (a linear variable's value starts the alternation between blocks).
  std::vector<std::vector<double>> xs;
  std::vector<double> defaults(n);
  for (std::size_t i = 0; i < n; ++i) defaults[i] = plan.variables[i].start;
  xs.push_back(defaults);
  std::vector<std::vector<int>> strata(n);
  for (auto& s : strata) {
    for (int p = 0; p + 1 < points; ++p) s.push_back(p);
    std::shuffle(s.begin(), s.end(), random);
  }
  for (int p = 0; p + 1 < points; ++p) {
    std::vector<double> x = defaults;
    for (std::size_t j = 0; j < n; ++j) {
      const Variable& v = plan.variables[j];
      x[j] = v.lo + (v.hi - v.lo) * (strata[j][std::size_t(p)] + uniform(random)) / (points - 1);
    }
    xs.push_back(std::move(x));
  }

  std::vector<Scored> scored;
  const int cycles = plan.blocks.size() > 1 ? 3 : 1;
  for (std::vector<double>& x : xs) {
    double cost = INFINITY;
    if (plan.blocks.empty()) {
      reference::Material material = plan.base;
      applyVariables(plan.variables, x.data(), material);
      cost = 0.0;
      for (const FitPair* pair : pairs) {
        const glm::dvec3 f = reference::eval(material, pair->wi, pair->wo);
        for (int c = 0; c < 3; ++c) {
          const double r = residual(metric, pair->f[c], f[c], pair->wi.z);
          cost += pair->weight * r * r;
        }
      }
      if (!std::isfinite(cost)) cost = INFINITY;
    }
    for (int cycle = 0; cycle < cycles; ++cycle) {
      for (const std::vector<int>& block : plan.blocks) cost = solveBlock(pairs, plan, block, metric, x);
    }
    scored.push_back({x, cost});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) { return a.cost < b.cost; });
  std::vector<Scored> chosen;
  for (const Scored& candidate : scored) {
    if (int(chosen.size()) == starts) break;
    bool distinct = true;
    for (const Scored& c : chosen) {
      bool near = true;
      for (int j : plan.nonlinear) {
        const Variable& v = plan.variables[std::size_t(j)];
        near &= std::abs(candidate.x[std::size_t(j)] - c.x[std::size_t(j)]) <= kDistinctStarts * (v.hi - v.lo);
      }
      distinct &= !near;
    }
    if (distinct) chosen.push_back(candidate);
  }
  return chosen;
}

struct BlockCost {
  const FitTarget* target;
  std::size_t first, count;
  const std::vector<Variable>* variables;
  reference::Material base;
  FitMetric metric;

  bool operator()(double const* const* parameters, double* residuals) const {
    reference::Material material = base;
    applyVariables(*variables, parameters[0], material);
    for (std::size_t k = 0; k < count; ++k) {
      const FitPair& pair = target->pairs[first + k];
      const glm::dvec3 f = reference::eval(material, pair.wi, pair.wo);
      const double w = std::sqrt(pair.weight);
      for (int c = 0; c < 3; ++c) residuals[3 * k + c] = w * residual(metric, pair.f[c], f[c], pair.wi.z);
    }
    return true;
  }
};

struct StartResult {
  std::vector<double> x;
  double cost = INFINITY;
  double seconds = 0.0;
  int iterations = 0;
  bool failed = false;
};

StartResult solveStart(const FitTarget& target, const ModelPlan& plan, std::vector<double> x, FitMetric metric,
                       int maxIterations = kMaxIterations) {
  const Stopwatch clock;
  const std::vector<Variable>& variables = plan.variables;
  ceres::Problem problem;
  const int n = int(variables.size());
  problem.AddParameterBlock(x.data(), n);
  for (int i = 0; i < n; ++i) {
    problem.SetParameterLowerBound(x.data(), i, variables[i].lo);
    problem.SetParameterUpperBound(x.data(), i, variables[i].hi);
  }
  for (std::size_t first = 0; first < target.pairs.size(); first += kPairsPerBlock) {
    const std::size_t count = std::min(kPairsPerBlock, target.pairs.size() - first);
    auto* cost = new ceres::DynamicNumericDiffCostFunction<BlockCost>(
        new BlockCost{&target, first, count, &variables, plan.base, metric});
    cost->AddParameterBlock(n);
    cost->SetNumResiduals(int(3 * count));
    problem.AddResidualBlock(cost, nullptr, x.data());
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = maxIterations;
  // Relative tolerances far below what a fit's error can show (its 4th digit) and far above rounding.
  options.function_tolerance = 1e-10;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-10;
  options.num_threads = 1;  // the starts run in parallel instead: the same seed then gives the same fits
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  StartResult result;
  result.x = std::move(x);
  result.cost = summary.final_cost;
  result.failed = !summary.IsSolutionUsable() || !std::isfinite(summary.final_cost);
  result.iterations = int(summary.iterations.size());
  result.seconds = clock.seconds();
  return result;
}

gpu::MaterialRecord recordOf(const ModelPlan& plan, const std::vector<double>& x) {
  reference::Material material = plan.base;
  applyVariables(plan.variables, x.data(), material);
  gpu::MaterialRecord record = defaultRecord(plan.model->id);
  for (std::uint32_t i = 0; i < gpu::kMaxMaterialParams; ++i) record.params[i] = float(material.params[i]);
  return record;
}

// What a fit should say about itself (FitResult::warnings), and its unconstrained variables set to their defaults.
std::vector<std::string> reviewFit(const FitTarget& target, const ModelPlan& plan, std::vector<double>& x,
                                   FitMetric metric) {
  std::vector<std::string> warnings;
  const auto costAt = [&](const std::vector<double>& at) {
    return fitError(target, recordOf(plan, at), metric);
  };
  // A parameter the data does not constrain: its whole range (and its default) fits as well as the fitted value.
  const double best = costAt(x);
  // Rounding of an exact fit leaves errors near 1e-17 of the target: a change below 1e-9 of the target's own RMS
  // is not one the data shows.
  gpu::MaterialRecord black = defaultRecord(modelId("lambert"));
  setParam(black, "rho_d", glm::vec3(0.0f), "fit");
  const double floor = 1e-9 * fitError(target, black, metric);
  for (std::size_t i = 0; i < plan.variables.size(); ++i) {
    const Variable& v = plan.variables[i];
    std::vector<double> probe = x;
    bool free = true;
    for (double value : {v.lo, v.hi, 0.5 * (v.lo + v.hi), v.start}) {
      probe[i] = value;
      free &= costAt(probe) <= best * (1.0 + 1e-6) + floor;
    }
    if (!free) continue;
    x[i] = v.start;
    std::string name = "?";
    for (const ParamInfo& p : plan.model->params) {
      if (v.slots[0] >= p.slot && v.slots[0] < p.slot + (p.rgb ? 3u : 1u)) {
        name = std::string(p.name);
        if (p.rgb) name += std::string("[") + "rgb"[v.slots[0] - p.slot] + "]";
      }
    }
    warnings.push_back(name + " is not constrained by the data (any value in its range fits as well); reported at "
                       "its default");
  }
  // A term the data shows that the fit left out: away from the highlight (theta_h > 20 degrees), where a glossy
  // lobe has fallen off, the fit reflects under half of what the target does in a channel that carries at least
  // 2% of the target's reflected light there.
  const reference::Material material = reference::fromRecord(recordOf(plan, x));
  glm::dvec3 targetFar(0.0), modelFar(0.0), targetAll(0.0);
  const double cos20 = std::cos(20.0 * 3.14159265358979323846 / 180.0);
  for (const FitPair& pair : target.pairs) {
    targetAll += pair.weight * pair.f * pair.wi.z;
    if (glm::normalize(pair.wi + pair.wo).z >= cos20) continue;
    targetFar += pair.weight * pair.f * pair.wi.z;
    modelFar += pair.weight * reference::eval(material, pair.wi, pair.wo) * pair.wi.z;
  }
  for (int c = 0; c < 3; ++c) {
    if (targetFar[c] > 0.02 * targetAll[c] && modelFar[c] < 0.5 * targetFar[c]) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "away from the highlight (theta_h > 20 deg) the fit reflects %.0f%% of the target's %s: a term "
                    "the data shows (a diffuse floor?) is left near zero",
                    100.0 * modelFar[c] / targetFar[c], c == 0 ? "red" : c == 1 ? "green" : "blue");
      warnings.emplace_back(text);
      break;
    }
  }
  return warnings;
}

}  // namespace

FitMetric parseFitMetric(const std::string& text, const std::string& where) {
  if (text == "cosine") return FitMetric::kCosine;
  if (text == "log") return FitMetric::kLog;
  throw Error(where + ": the metric is cosine or log, not '" + text + "'");
}

const char* fitMetricName(FitMetric metric) { return metric == FitMetric::kCosine ? "cosine" : "log"; }

std::vector<std::string> fittableModels() {
  std::vector<std::string> names;
  for (const ModelInfo& model : allModels()) {
    bool file = false;
    for (const ParamInfo& p : model.params) file |= isFileParam(p);
    // The library's models: a model of the test tree (registered by test builds) is fitted only when named.
    if (!isDeltaOnly(model) && !file && !model.glslFile.starts_with("tests/")) names.emplace_back(model.name);
  }
  return names;
}

std::vector<std::pair<std::string, std::vector<double>>> fitParams(const FitResult& fit) {
  std::vector<std::pair<std::string, std::vector<double>>> params;
  for (const ParamInfo& param : modelInfo(fit.record.model).params) {
    std::vector<double> values;
    for (int c = 0; c < (param.rgb ? 3 : 1); ++c) values.push_back(fit.record.params[param.slot + c]);
    params.emplace_back(std::string(param.name), values);
  }
  return params;
}

std::string fitParamList(const FitResult& fit) {
  std::string text;
  for (const ParamInfo& param : modelInfo(fit.record.model).params) {
    char value[96];
    const float* v = &fit.record.params[param.slot];
    if (param.rgb) {
      std::snprintf(value, sizeof value, "%.6g/%.6g/%.6g", double(v[0]), double(v[1]), double(v[2]));
    } else {
      std::snprintf(value, sizeof value, "%.6g", double(v[0]));
    }
    text += (text.empty() ? "" : ",") + std::string(param.name) + "=" + value;
  }
  return text;
}

double fitError(const FitTarget& target, const gpu::MaterialRecord& record, FitMetric metric, double* relativeError) {
  const reference::Material material = reference::fromRecord(record);
  double sum = 0.0, targetSum = 0.0;
  for (const FitPair& pair : target.pairs) {
    const glm::dvec3 f = reference::eval(material, pair.wi, pair.wo);
    for (int c = 0; c < 3; ++c) {
      const double r = residual(metric, pair.f[c], f[c], pair.wi.z);
      const double t = residual(metric, pair.f[c], 0.0, pair.wi.z);
      sum += pair.weight * r * r;
      targetSum += pair.weight * t * t;
    }
  }
  const double error = std::sqrt(sum / 3.0);
  if (relativeError != nullptr) *relativeError = targetSum > 0.0 ? error / std::sqrt(targetSum / 3.0) : 0.0;
  return error;
}

std::vector<FitResult> fitModels(const FitTarget& target, const FitOptions& options) {
  if (target.pairs.empty()) throw Error(target.name + ": nothing to fit (no direction pairs)");
  if (options.starts < 1) throw Error("raylab brdf fit: at least one start", kExitUsage);
  if (options.searchPoints < 0) throw Error("raylab brdf fit: the search points are 0 or more", kExitUsage);
  const std::vector<std::string> names = options.models.empty() ? fittableModels() : options.models;
  const bool isotropic = options.isotropic.value_or(target.isotropic);
  std::vector<ModelPlan> plans;
  for (const std::string& name : names) {
    const ModelInfo* model = findModel(name);
    bool file = false;
    if (model != nullptr) {
      for (const ParamInfo& p : model->params) file |= isFileParam(p);
    }
    if (model == nullptr || isDeltaOnly(*model) || file) {
      std::string list;
      for (const std::string& f : fittableModels()) list += (list.empty() ? "" : ", ") + f;
      throw Error("raylab brdf fit: '" + name + "' is not a model that can be fitted (" + list + ")", kExitUsage);
    }
    for (const ModelPlan& plan : plans) {
      if (plan.model == model) throw Error("raylab brdf fit: '" + name + "' is named twice", kExitUsage);
    }
    plans.push_back(planOf(*model, isotropic));
  }

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // Each thread holds one solve's Jacobian (3 residuals per pair, a column per variable, in doubles) and its
  // residual blocks: never more threads than cores, and no more than a quarter of this budget's worth.
  constexpr double kMemoryBudgetBytes = 4.0 * 1024 * 1024 * 1024;
  std::size_t widest = 1;
  for (const ModelPlan& plan : plans) widest = std::max(widest, plan.variables.size() + 1);
  const double perThread = double(target.pairs.size()) * 3.0 * double(widest) * 8.0 * 2.0;
  const unsigned memoryThreads = unsigned(std::max(1.0, kMemoryBudgetBytes / perThread));
  const unsigned threadLimit = std::min({cores, memoryThreads, options.threads > 0 ? unsigned(options.threads) : cores});

  int done = 0;
  // Known once each search has chosen its starts (a model with no nonlinear parameter needs only one).
  const bool searched = options.searchPoints > 0;
  int total = int(plans.size()) * (options.starts + (searched ? 1 : 0) +
                                   (searched && target.pairs.size() > 2 * kSearchPairs ? 1 : 0));

  // Each model is a chain of steps: its search, its LM starts (the search's best distinct points, or without a
  // search the defaults and random points), and, when the starts saw the coarse pairs, its best start polished on
  // every pair. The steps of all models share the threads, a step becoming ready when its chain reaches it, those of
  // the models with the most variables first so that the cores finish together. Every step's result depends only on
  // its inputs: the same seed gives the same fits however the steps interleave.
  const bool coarseToFine = options.searchPoints > 0 && target.pairs.size() > 2 * kSearchPairs;
  const FitTarget coarse = options.searchPoints > 0 ? coarseTarget(target) : FitTarget{};
  const FitTarget& startTarget = coarseToFine ? coarse : target;
  struct Chain {
    std::vector<std::vector<double>> starts;
    std::vector<StartResult> results;
    int pending = 0;  // starts not finished
    StartResult best;
    double searchSeconds = 0.0;
  };
  std::vector<Chain> chains(plans.size());
  enum class Step { kSearch, kStart, kPolish };
  struct Task {
    Step step;
    std::size_t model;
    std::size_t start = 0;
  };
  std::vector<Task> ready;
  std::mutex queueMutex;
  std::condition_variable wake;
  std::size_t running = 0;
  std::exception_ptr failure;
  const auto pushStarts = [&](std::size_t m) {  // queueMutex held
    Chain& chain = chains[m];
    chain.results.resize(chain.starts.size());
    chain.pending = int(chain.starts.size());
    for (std::size_t s = 0; s < chain.starts.size(); ++s) ready.push_back({Step::kStart, m, s});
  };
  for (std::size_t m = 0; m < plans.size(); ++m) {
    if (options.searchPoints > 0) {
      ready.push_back({Step::kSearch, m});
      continue;
    }
    std::mt19937_64 random(std::uint64_t(options.seed) * 1000003u + plans[m].model->id);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int s = 0; s < options.starts; ++s) {
      std::vector<double> x;
      for (const Variable& v : plans[m].variables) x.push_back(s == 0 ? v.start : v.lo + (v.hi - v.lo) * uniform(random));
      chains[m].starts.push_back(std::move(x));
    }
    pushStarts(m);
  }
  const auto finishStarts = [&](std::size_t m) {  // queueMutex held: the best start, to polish or keep
    Chain& chain = chains[m];
    const StartResult* best = nullptr;
    // Ties keep the earlier start: the order is fixed, so the choice is too.
    for (const StartResult& r : chain.results) {
      if (!r.failed && (best == nullptr || r.cost < best->cost)) best = &r;
    }
    if (best == nullptr) return;
    chain.best = *best;
    chain.best.seconds = 0.0;
    if (coarseToFine) ready.push_back({Step::kPolish, m});
  };
  const auto work = [&] {
    std::unique_lock lock(queueMutex);
    for (;;) {
      wake.wait(lock, [&] { return !ready.empty() || running == 0 || failure; });
      if (failure || (ready.empty() && running == 0)) return;
      // The step of the model with the most variables, later steps of a chain first.
      const auto first = std::min_element(ready.begin(), ready.end(), [&](const Task& a, const Task& b) {
        const std::size_t va = plans[a.model].variables.size(), vb = plans[b.model].variables.size();
        return va != vb ? va > vb : int(a.step) > int(b.step);
      });
      const Task task = *first;
      ready.erase(first);
      ++running;
      lock.unlock();
      std::string label = std::string(plans[task.model].model->name);
      double seconds = 0.0;
      try {
        Chain& chain = chains[task.model];
        if (task.step == Step::kSearch) {
          const Stopwatch clock;
          std::mt19937_64 random(std::uint64_t(options.seed) * 1000003u + plans[task.model].model->id);
          std::vector<Scored> found = searchBasins(coarse, plans[task.model], options.metric, options.searchPoints,
                                                   options.starts, random);
          for (Scored& start : found) chain.starts.push_back(std::move(start.x));
          seconds = chain.searchSeconds = clock.seconds();
          label += " search";
        } else if (task.step == Step::kStart) {
          chain.results[task.start] = solveStart(startTarget, plans[task.model], chain.starts[task.start],
                                                 options.metric, coarseToFine ? kMaxCoarseIterations : kMaxIterations);
          seconds = chain.results[task.start].seconds;
        } else {
          StartResult fine = solveStart(target, plans[task.model], chain.best.x, options.metric);
          seconds = fine.seconds;
          if (!fine.failed) chain.best = std::move(fine);
          label += " polish";
        }
      } catch (...) {
        lock.lock();
        if (!failure) failure = std::current_exception();
        --running;
        wake.notify_all();
        return;
      }
      lock.lock();
      --running;
      Chain& chain = chains[task.model];
      if (task.step == Step::kSearch) {
        pushStarts(task.model);
        total += int(chain.starts.size()) + (coarseToFine ? 1 : 0) - options.starts - (coarseToFine ? 1 : 0);
      } else if (task.step == Step::kStart && --chain.pending == 0) {
        finishStarts(task.model);
      }
      ++done;
      if (options.progress) options.progress(done, total, label, seconds);
      wake.notify_all();
    }
  };
  {
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threadLimit; ++t) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
  }
  if (failure) std::rethrow_exception(failure);

  std::vector<FitResult> fits;
  for (std::size_t m = 0; m < plans.size(); ++m) {
    FitResult fit;
    fit.model = std::string(plans[m].model->name);
    const Chain& chain = chains[m];
    fit.seconds = chain.searchSeconds + chain.best.seconds;
    for (const StartResult& r : chain.results) {
      fit.seconds += r.seconds;
      ++fit.starts;
      fit.failedStarts += r.failed ? 1 : 0;
    }
    if (fit.starts == 0 || fit.failedStarts == fit.starts) {
      throw Error("raylab brdf fit: every start of " + fit.model + " failed (" + std::to_string(fit.starts) +
                  " starts): the target's values may be out of the model's reach");
    }
    const StartResult* best = &chain.best;
    std::vector<double> x = best->x;
    fit.warnings = reviewFit(target, plans[m], x, options.metric);
    if (fit.failedStarts > 0) {
      fit.warnings.push_back(std::to_string(fit.failedStarts) + " of " + std::to_string(fit.starts) +
                             " starts failed and were left out");
    }
    fit.record = recordOf(plans[m], x);
    fit.iterations = best->iterations;
    fit.error = fitError(target, fit.record, options.metric, &fit.relativeError);
    if (!std::isfinite(fit.error)) {
      throw Error("raylab brdf fit: the error of " + fit.model + " overflows on " + target.name +
                  " (its values or the model's reach beyond a double)");
    }
    fits.push_back(fit);
  }
  // Best first; within 1e-6 of each other (a tie: the data cannot tell them apart) the model with fewer
  // variables first, the simpler explanation.
  std::stable_sort(fits.begin(), fits.end(), [](const FitResult& a, const FitResult& b) { return a.error < b.error; });
  for (std::size_t i = 1; i < fits.size(); ++i) {
    for (std::size_t k = i; k > 0; --k) {
      FitResult& a = fits[k - 1];
      FitResult& b = fits[k];
      const auto count = [&](const FitResult& f) {
        for (const ModelPlan& plan : plans) {
          if (plan.model->name == f.model) return plan.variables.size();
        }
        return std::size_t(0);
      };
      const bool tie = std::abs(a.error - b.error) <= 1e-6 * std::max(a.error, b.error) + 1e-300;
      if (!(tie && count(b) < count(a))) break;
      std::swap(a, b);
    }
  }
  return fits;
}

}  // namespace raylab
