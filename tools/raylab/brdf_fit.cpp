// `raylab brdf fit`: every analytic model of the library (or those named) fitted to a target, ranked
// (engine/fit, docs/fitting.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "brdf_commands.h"
#include "brdf_params/material_params.h"
#include "command_line/cli.h"
#include "fit/fit.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/progress.h"
#include "util/timer.h"

namespace raylab {

namespace {

constexpr const char* kCommand = "raylab brdf fit";

struct FitCommandOptions {
  std::string target;
  std::string models;
  std::string metric = "cosine";
  std::optional<std::uint32_t> starts;  // empty: each model's own (fit.h)
  std::uint32_t seed = 1;
  std::uint32_t search = 256;
  std::uint32_t threads = 0;
  bool isotropic = false;
  bool anisotropic = false;
  std::string jsonPath;
};

std::vector<std::string> splitModels(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    std::string name = text.substr(start, end - start);
    while (!name.empty() && name.front() == ' ') name.erase(name.begin());
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name.empty()) throw Error(std::string(kCommand) + ": --models has an empty entry: '" + text + "'", kExitUsage);
    names.push_back(name);
    start = end + 1;
  }
  return names;
}

int fit(const FitCommandOptions& o) {
  if (!o.jsonPath.empty()) {
    checkOutputPath(o.jsonPath, "--json");
    requireExtension(kCommand, "--json", o.jsonPath, ".json");
    // A ranking written over its own target would destroy the measurement.
    std::error_code error;
    if (std::filesystem::equivalent(o.jsonPath, o.target, error)) {
      throw Error(std::string(kCommand) + ": --json " + o.jsonPath + " is the target itself", kExitUsage);
    }
  }
  FitOptions options;
  options.starts = o.starts ? int(*o.starts) : 0;
  options.seed = o.seed;
  options.threads = int(o.threads);
  options.searchPoints = int(o.search);
  if (o.isotropic && o.anisotropic) {
    throw Error(std::string(kCommand) + ": --isotropic and --anisotropic exclude each other", kExitUsage);
  }
  if (o.isotropic) options.isotropic = true;
  if (o.anisotropic) options.isotropic = false;
  try {
    options.metric = parseFitMetric(o.metric, std::string(kCommand) + ": --metric");
    if (!o.models.empty()) options.models = splitModels(o.models);
  } catch (const Error& error) {
    throw Error(error.what(), kExitUsage);
  }
  const Stopwatch clock;
  const FitTarget target = loadFitTarget(o.target);
  const bool isotropic = options.isotropic.value_or(target.isotropic);
  std::fprintf(stderr, "%s: %s: %s\n", kCommand, o.target.c_str(), summarizeTarget(target).text().c_str());
  std::fprintf(stderr, "%s: %s error, %s, %s, %s\n", kCommand,
               fitMetricName(options.metric), isotropic ? "isotropic (x and y parameters tied)" : "anisotropic",
               describeSearch(options).c_str(), describeStarts(options).c_str());
  // One line per finished start on a log, redrawn on a terminal: starts done, elapsed, ETA.
  options.progress = [&](int done, int total, const std::string& model, double seconds) {
    const double elapsed = clock.seconds();
    // The last step says it is the last rather than "ETA 0 us".
    const std::string eta = done < total ? "ETA " + formatSeconds(elapsed / done * (total - done)) : "done";
    std::fprintf(stderr, "%s: %d/%d steps, %s in %s, elapsed %s, %s\n", kCommand, done, total, model.c_str(),
                 formatSeconds(seconds).c_str(), formatSeconds(elapsed).c_str(), eta.c_str());
  };
  const std::vector<FitResult> fits = fitModels(target, options);

  std::printf("%-4s %-18s %-12s %-10s %-9s %s\n", "rank", "model", "error", "relative", "seconds", "parameters");
  nlohmann::json json = nlohmann::json::array();
  for (std::size_t i = 0; i < fits.size(); ++i) {
    const FitResult& f = fits[i];
    std::printf("%-4zu %-18s %-12.6g %-10.4f %-9.2f %s\n", i + 1, f.model.c_str(), f.error, f.relativeError,
                f.seconds, fitParamList(f).c_str());
    for (const std::string& warning : f.warnings) {
      std::fprintf(stderr, "%s: warning: %s: %s\n", kCommand, f.model.c_str(), warning.c_str());
    }
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [name, values] : fitParams(f)) {
      params[name] = values.size() == 1 ? nlohmann::json(values[0]) : nlohmann::json(values);
    }
    json.push_back({{"model", f.model}, {"params", params}, {"error", f.error}, {"relative_error", f.relativeError},
                    {"seconds", f.seconds}, {"iterations", f.iterations}, {"starts", f.starts},
                    {"failed_starts", f.failedStarts}, {"warnings", f.warnings},
                    {"metric", fitMetricName(options.metric)}, {"isotropic", isotropic}, {"target", o.target}});
  }
  if (!o.jsonPath.empty()) writeFileAtomically(o.jsonPath, json.dump(2) + "\n");
  std::fprintf(stderr, "%s: %zu models in %s%s%s\n", kCommand, fits.size(),
               formatSeconds(clock.seconds()).c_str(), o.jsonPath.empty() ? "" : "; wrote ", o.jsonPath.c_str());
  return kExitOk;
}

}  // namespace

void addBrdfFitCommand(CLI::App& brdf) {
  auto o = std::make_shared<FitCommandOptions>();
  CLI::App* command = addCommand(
      brdf, "fit",
      "fit every analytic model of the library to a measured material or another model, and rank them\n"
      "TARGET is a MERL .binary file, a MERL phi_d = 90 .slice, a .csv of measured samples (header "
      "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b[,weight]), or a material of the library as MODEL[:k=v,...] (for "
      "example ggx_conductor:metal=Au). Each sample weighs its share of the measure (a .csv: its weight column, or "
      "equal weights). Each model's parameters are fitted within their ranges: a search of --search points of the "
      "nonlinear parameters, with those that enter f linearly (colours) solved by least squares, then Ceres "
      "Solver's Levenberg-Marquardt from the best --starts distinct points, minimising the weighted RMS of "
      "f cos(theta_i) over the pairs within 80 degrees of the normal (--metric cosine, Ngan et al. 2005) or of "
      "log(1 + f cos(theta_i)) (--metric log). Prints what the target holds, then a ranking (model, error, error "
      "relative to the target's own RMS, CPU seconds, parameters as --material takes them) and a warning for a fit "
      "that left out a term the data shows or a parameter the data does not constrain; --json writes it as a "
      "list, best first (docs/fitting.md).",
      [o] { return fit(*o); });
  addPositional(command, "TARGET", o->target, "a .binary MERL file, a .csv of samples, or MODEL[:k=v,...]");
  addText(command, "--models", o->models, "a,b,...", "fit only these models (default: " + [] {
    std::string list;
    for (const std::string& m : fittableModels()) list += (list.empty() ? "" : ", ") + m;
    return list;
  }() + ")");
  addChoice(command, "--metric", o->metric, {"cosine", "log"}, "the error minimised and reported");
  addOptionalCount(command, "--starts", o->starts,
                   "Levenberg-Marquardt starts per model: the search's best distinct points (default: " +
                       describeStarts(FitOptions{}) + ")",
                   1, 64);
  addCount(command, "--search", o->search,
           "points of the search per model (0: no search; the starts are the defaults, then random points; "
           "default: " + describeSearch(FitOptions{}) + ")", 0,
           65536);
  addFlag(command, "--isotropic", o->isotropic,
          "tie x and y parameters (alpha_x = alpha_y, nu = nv); the default for MERL files and slices");
  addFlag(command, "--anisotropic", o->anisotropic, "fit x and y parameters apart, also for a MERL file or slice");
  addCount(command, "--seed", o->seed, "seed of the random starts: the same seed gives the same fits", 0, UINT32_MAX);
  addCount(command, "--threads", o->threads, "starts solved at once (0 or more than the cores: one per core)", 0, 256);
  addText(command, "--json", o->jsonPath, "FILE.json", "also write the ranking as JSON");
}

}  // namespace raylab
