#include "fit/fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <atomic>
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

// One optimisation variable: the parameter floats it sets (an RGB channel, or a slope_x tied with its slope_y),
// in log space for log-scaled parameters.
struct Variable {
  std::vector<std::uint32_t> slots;
  bool log = false;
  double lo = 0.0, hi = 1.0;  // in the variable's space
  double start = 0.0;         // the default
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

double residual(FitMetric metric, double target, double model, double cosine) {
  return metric == FitMetric::kCosine ? (target - model) * cosine
                                      : std::log1p(target * cosine) - std::log1p(std::max(0.0, model) * cosine);
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
};

StartResult solveStart(const FitTarget& target, const ModelInfo& model, const std::vector<Variable>& variables,
                       std::vector<double> x, FitMetric metric) {
  const Stopwatch clock;
  const reference::Material base = reference::fromRecord(defaultRecord(model.id));
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
        new BlockCost{&target, first, count, &variables, base, metric});
    cost->AddParameterBlock(n);
    cost->SetNumResiduals(int(3 * count));
    problem.AddResidualBlock(cost, nullptr, x.data());
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = kMaxIterations;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-12;
  options.num_threads = 1;  // the starts run in parallel instead: the same seed then gives the same fits
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  StartResult result;
  result.x = std::move(x);
  result.cost = summary.final_cost;
  result.iterations = int(summary.iterations.size());
  result.seconds = clock.seconds();
  return result;
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
  if (options.starts < 1) throw Error("raylab brdf fit: at least one start");
  const std::vector<std::string> names = options.models.empty() ? fittableModels() : options.models;
  struct Job {
    std::size_t model;
    std::vector<double> x;
  };
  std::vector<const ModelInfo*> models;
  std::vector<std::vector<Variable>> variables;
  std::vector<Job> jobs;
  for (const std::string& name : names) {
    const ModelInfo* model = findModel(name);
    bool file = false;
    if (model != nullptr) {
      for (const ParamInfo& p : model->params) file |= isFileParam(p);
    }
    if (model == nullptr || isDeltaOnly(*model) || file) {
      std::string list;
      for (const std::string& f : fittableModels()) list += (list.empty() ? "" : ", ") + f;
      throw Error("raylab brdf fit: '" + name + "' is not a model that can be fitted (" + list + ")");
    }
    if (std::find(models.begin(), models.end(), model) != models.end()) {
      throw Error("raylab brdf fit: '" + name + "' is named twice");
    }
    models.push_back(model);
    variables.push_back(variablesOf(*model, target.isotropic));
    std::mt19937_64 random(std::uint64_t(options.seed) * 1000003u + model->id);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int s = 0; s < options.starts; ++s) {
      std::vector<double> x;
      for (const Variable& v : variables.back()) x.push_back(s == 0 ? v.start : v.lo + (v.hi - v.lo) * uniform(random));
      jobs.push_back({models.size() - 1, std::move(x)});
    }
  }

  // The starts with the most variables first, so that two cores finish together (the longest-first schedule).
  std::vector<std::size_t> order(jobs.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return jobs[a].x.size() > jobs[b].x.size();
  });
  std::vector<StartResult> results(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex progressMutex;
  int done = 0;
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t n = next++; n < jobs.size(); n = next++) {
      const std::size_t j = order[n];
      try {
        results[j] = solveStart(target, *models[jobs[j].model], variables[jobs[j].model], jobs[j].x, options.metric);
      } catch (...) {
        const std::lock_guard lock(progressMutex);
        if (!failure) failure = std::current_exception();
      }
      const std::lock_guard lock(progressMutex);
      ++done;
      if (options.progress) {
        options.progress(done, int(jobs.size()), std::string(models[jobs[j].model]->name), results[j].seconds);
      }
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned threads = std::min<unsigned>(options.threads > 0 ? unsigned(options.threads) : cores, jobs.size());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);

  std::vector<FitResult> fits;
  for (std::size_t m = 0; m < models.size(); ++m) {
    FitResult fit;
    fit.model = std::string(models[m]->name);
    const StartResult* best = nullptr;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (jobs[j].model != m) continue;
      fit.seconds += results[j].seconds;
      // Ties keep the earlier start: the order is fixed, so the choice is too.
      if (best == nullptr || results[j].cost < best->cost) best = &results[j];
    }
    reference::Material material = reference::fromRecord(defaultRecord(models[m]->id));
    applyVariables(variables[m], best->x.data(), material);
    fit.record = defaultRecord(models[m]->id);
    for (std::uint32_t i = 0; i < gpu::kMaxMaterialParams; ++i) fit.record.params[i] = float(material.params[i]);
    fit.iterations = best->iterations;
    fit.error = fitError(target, fit.record, options.metric, &fit.relativeError);
    fits.push_back(fit);
  }
  std::stable_sort(fits.begin(), fits.end(), [](const FitResult& a, const FitResult& b) { return a.error < b.error; });
  return fits;
}

}  // namespace raylab
