#include "fit/fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <limits>
#include <mutex>
#include <random>
#include <thread>

#include "brdf_params/material_params.h"
#include "fit/fit_plan.h"
#include "fit/fit_search.h"
#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "util/error.h"
#include "util/timer.h"

namespace raylab {

using namespace fitting;

namespace {

// Residual blocks of this many pairs: few enough blocks that Ceres' bookkeeping stays small.
constexpr std::size_t kPairsPerBlock = 256;
constexpr int kMaxIterations = 100;
// A start on the coarse pairs only has to reach its basin: the polish on every pair finishes it.
constexpr int kMaxCoarseIterations = 30;
// And the polish starts in the basin: past 15 iterations it changed no fit's relative error by more than 0.3%
// (SGD, which crawls along its valleys for 95 iterations, on four slices), at twice the cost.
constexpr int kMaxPolishIterations = 30;
// The channel search's grid of about 144 points a channel is 12 x 12 for a conductor's two nonlinear colours, and
// 2 a side for SGD's eight, too coarse to find anything (it changed no SGD fit tried): models with more skip it.
constexpr std::size_t kChannelSearchColours = 2;

// One block of pairs' residuals and their Jacobian by forward differences, as Ceres' numeric differentiation takes
// them (step max(sqrt(eps), 1e-6 |x|)), but with the columns in the plan's difference groups (ModelPlan::diffGroups):
// variables that each move one channel of f, a different one, share one evaluation. SGD's 30 variables cost 11
// evaluations a pair instead of 31, the conductor's 10 cost 5.
class BlockCost final : public ceres::CostFunction {
 public:
  BlockCost(const FitTarget& target, std::size_t first, std::size_t count, const ModelPlan& plan, FitMetric metric)
      : target_(target), first_(first), count_(count), plan_(plan), metric_(metric) {
    set_num_residuals(int(3 * count));
    mutable_parameter_block_sizes()->push_back(int(plan.variables.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::size_t n = plan_.variables.size();
    const double* x = parameters[0];
    evaluate(x, residuals);
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;
    double* J = jacobians[0];
    std::vector<double> moved(x, x + n), shifted(3 * count_);
    for (const std::vector<int>& group : plan_.diffGroups) {
      for (int j : group) {
        moved[std::size_t(j)] = x[j] + step(x[j]);
      }
      evaluate(moved.data(), shifted.data());
      for (int j : group) {
        const double h = moved[std::size_t(j)] - x[j];
        const int channel = plan_.variables[std::size_t(j)].channel;
        for (std::size_t r = 0; r < 3 * count_; ++r) {
          const bool seen = channel < 0 || int(r % 3) == channel;
          J[r * n + std::size_t(j)] = seen ? (shifted[r] - residuals[r]) / h : 0.0;
        }
        moved[std::size_t(j)] = x[j];
      }
    }
    return true;
  }

 private:
  static double step(double x) {
    return std::max(std::sqrt(std::numeric_limits<double>::epsilon()), 1e-6 * std::abs(x));
  }

  void evaluate(const double* x, double* residuals) const {
    reference::Material material = plan_.base;
    applyVariables(plan_.variables, x, material);
    for (std::size_t k = 0; k < count_; ++k) {
      const FitPair& pair = target_.pairs[first_ + k];
      const glm::dvec3 f = reference::eval(material, pair.wi, pair.wo);
      const double w = std::sqrt(pair.weight);
      for (int c = 0; c < 3; ++c) residuals[3 * k + c] = w * residual(metric_, pair.f[c], f[c], pair.wi.z);
    }
  }

  const FitTarget& target_;
  std::size_t first_, count_;
  const ModelPlan& plan_;
  FitMetric metric_;
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
    problem.AddResidualBlock(new BlockCost(target, first, count, plan, metric), nullptr, x.data());
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

std::vector<std::string> fittableModels(bool byName) {
  std::vector<std::string> names;
  for (const ModelInfo& model : allModels()) {
    bool file = false;
    for (const ParamInfo& p : model.params) file |= isFileParam(p);
    // The library's models: a model of the test tree (registered by test builds) is fitted only when named.
    // A model whose registry line says `fit: by name` likewise.
    if (!isDeltaOnly(model) && !file && !model.glslFile.starts_with("tests/") && (byName || model.fitByName.empty())) {
      names.emplace_back(model.name);
    }
  }
  return names;
}

std::string describeStarts(const FitOptions& options) {
  if (options.starts > 0) return std::to_string(options.starts) + " LM starts per model";
  std::string text = std::to_string(kDefaultStarts) + " LM starts per model";
  for (const ModelInfo& model : allModels()) {
    if (model.fitStarts > 0 && int(model.fitStarts) != kDefaultStarts) {
      text += ", " + std::string(model.name) + " " + std::to_string(model.fitStarts);
    }
  }
  return text;
}

std::string describeSearch(const FitOptions& options) {
  if (options.searchPoints == 0) return "no search";
  std::string text = "search of " + std::to_string(options.searchPoints) + " points per model";
  for (const ModelInfo& model : allModels()) {
    if (model.fitSearchFactor > 1) {
      text += ", " + std::string(model.name) + " " + std::to_string(options.searchPoints * model.fitSearchFactor);
    }
  }
  return text;
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
  if (options.starts < 0) throw Error("raylab brdf fit: the starts are 1 or more (0: each model's own)", kExitUsage);
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

  const auto startsOf = [&](const ModelPlan& plan) {
    if (options.starts > 0) return options.starts;
    return plan.model->fitStarts > 0 ? int(plan.model->fitStarts) : kDefaultStarts;
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // Each thread holds one solve's Jacobian (3 residuals per pair, a column per variable, in doubles) and as much
  // again in residual blocks: never more threads than cores, nor more than this budget holds (a million-pair CSV
  // with --threads 256 used to take 6 GiB).
  constexpr double kMemoryBudgetBytes = 4.0 * 1024 * 1024 * 1024;
  std::size_t widest = 1;
  for (const ModelPlan& plan : plans) widest = std::max(widest, plan.variables.size() + 1);
  const double perThread = double(target.pairs.size()) * 3.0 * double(widest) * 8.0 * 2.0;
  const unsigned memoryThreads = unsigned(std::max(1.0, kMemoryBudgetBytes / perThread));
  const unsigned threadLimit = std::min({cores, memoryThreads, options.threads > 0 ? unsigned(options.threads) : cores});

  int done = 0;
  // Known once each search has chosen its starts (a model with no nonlinear parameter needs only one).
  const bool searched = options.searchPoints > 0;
  int total = 0;
  for (const ModelPlan& plan : plans) {
    total += startsOf(plan) + (searched ? 1 : 0) + (searched && target.pairs.size() > 2 * kSearchPairs ? 1 : 0);
  }

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
    double channelSearchSeconds = 0.0;
    double lobeSearchSeconds = 0.0;
  };
  std::vector<Chain> chains(plans.size());
  enum class Step { kSearch, kStart, kChannelSearch, kLobeSearch, kPolish };
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
    for (int s = 0; s < startsOf(plans[m]); ++s) {
      std::vector<double> x;
      for (const Variable& v : plans[m].variables) x.push_back(s == 0 ? v.start : v.lo + (v.hi - v.lo) * uniform(random));
      chains[m].starts.push_back(std::move(x));
    }
    pushStarts(m);
  }
  // After the starts: the channel search (a model with nonlinear colours), the lobe search (a model with lobes), then
  // the polish on every pair (when the starts saw the coarse pairs); each step only where it applies.
  const auto advance = [&](std::size_t m, Step finished) {  // queueMutex held
    if (searched && finished < Step::kChannelSearch && !plans[m].nonlinearColours.empty() &&
        plans[m].nonlinearColours.size() <= kChannelSearchColours) {
      ready.push_back({Step::kChannelSearch, m});
      ++total;
    } else if (searched && finished < Step::kLobeSearch && !plans[m].lobes.empty()) {
      ready.push_back({Step::kLobeSearch, m});
      ++total;
    } else if (coarseToFine && finished < Step::kPolish) {
      ready.push_back({Step::kPolish, m});
    }
  };
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
    advance(m, Step::kStart);
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
          const int points = options.searchPoints * int(plans[task.model].model->fitSearchFactor);
          std::vector<Scored> found = searchBasins(coarse, plans[task.model], options.metric, points,
                                                   startsOf(plans[task.model]), random);
          for (Scored& start : found) chain.starts.push_back(std::move(start.x));
          seconds = chain.searchSeconds = clock.seconds();
          label += " search";
        } else if (task.step == Step::kStart) {
          chain.results[task.start] = solveStart(startTarget, plans[task.model], chain.starts[task.start],
                                                 options.metric, coarseToFine ? kMaxCoarseIterations : kMaxIterations);
          seconds = chain.results[task.start].seconds;
        } else if (task.step == Step::kChannelSearch) {
          const Stopwatch clock;
          StartResult fromGrid = solveStart(startTarget, plans[task.model],
                                            channelSearch(coarse, plans[task.model], options.metric, chain.best.x),
                                            options.metric, coarseToFine ? kMaxCoarseIterations : kMaxIterations);
          if (!fromGrid.failed && fromGrid.cost < chain.best.cost) {
            fromGrid.seconds = 0.0;
            chain.best = std::move(fromGrid);
          }
          seconds = chain.channelSearchSeconds = clock.seconds();
          label += " channel search";
        } else if (task.step == Step::kLobeSearch) {
          const Stopwatch clock;
          std::mt19937_64 random(std::uint64_t(options.seed) * 1000003u + plans[task.model].model->id + 7919u);
          const std::vector<double> regrown = lobeSearch(coarse, plans[task.model], options.metric, chain.best.x,
                                                         std::max(32, options.searchPoints / 2), random);
          if (!regrown.empty()) {
            StartResult fromLobe = solveStart(startTarget, plans[task.model], regrown, options.metric,
                                              coarseToFine ? kMaxCoarseIterations : kMaxIterations);
            if (!fromLobe.failed && fromLobe.cost < chain.best.cost) {
              fromLobe.seconds = 0.0;
              chain.best = std::move(fromLobe);
            }
          }
          seconds = chain.lobeSearchSeconds = clock.seconds();
          label += " lobe search";
        } else {
          StartResult fine = solveStart(target, plans[task.model], chain.best.x, options.metric, kMaxPolishIterations);
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
        total += int(chain.starts.size()) - startsOf(plans[task.model]);
      } else if (task.step == Step::kStart && --chain.pending == 0) {
        finishStarts(task.model);
      } else if (task.step == Step::kChannelSearch || task.step == Step::kLobeSearch) {
        advance(task.model, task.step);
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
    fit.seconds = chain.searchSeconds + chain.channelSearchSeconds + chain.lobeSearchSeconds + chain.best.seconds;
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
