// Fitting the analytic models of the library to a target (fit_target.h): each model's parameters within their
// ranges (log-scaled ones in log space; x/y pairs tied for an isotropic target) minimising a stated error over the
// target's direction pairs, by Ceres Solver's Levenberg-Marquardt from several starts (docs/fitting.md).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fit/fit_target.h"
#include "shared/scene_records.h"

namespace raylab {

// The error a fit minimises, per pair and channel, weighted by the pair's weight (docs/fitting.md):
//   cosine: f cos_i, the target's minus the model's (Ngan, Durand & Matusik, EGSR 2005);
//   log:    log(1 + f cos_i), the target's minus the model's (compresses highlights: tails weigh more).
enum class FitMetric { kCosine, kLog };
FitMetric parseFitMetric(const std::string& text, const std::string& where);
const char* fitMetricName(FitMetric metric);

constexpr int kDefaultStarts = 4;

struct FitOptions {
  std::vector<std::string> models;  // empty: every model fitModels can fit
  FitMetric metric = FitMetric::kCosine;
  // The search (docs/fitting.md, "How a fit finds its basin"): `searchPoints` points of the nonlinear parameters
  // (the defaults, then a stratified random sample of their box) are scored with the parameters that enter f
  // linearly solved in closed form; Levenberg-Marquardt then starts from the best `starts` distinct ones.
  // searchPoints 0: no search, the LM starts are the defaults and random points of the whole box (the plain
  // multi-start of tools/fit_basins.py's reference). starts 0: each model's own count, kDefaultStarts unless its
  // registry line `fit: starts N` says more (a model whose basins the default count measurably misses).
  int starts = 0;
  int searchPoints = 256;
  unsigned seed = 1;                // of the random points: the same seed gives the same fits
  int threads = 0;                  // starts solved at once; 0: one per core (never more than the cores)
  std::optional<bool> isotropic;    // tie x and y parameters; empty: as the target says (MERL files and slices)
  // Called after each start, from the thread that solved it, one call at a time.
  std::function<void(int startsDone, int startsTotal, const std::string& model, double seconds)> progress;
};

struct FitResult {
  std::string model;
  gpu::MaterialRecord record;  // the fitted material (every other parameter at its default)
  double error = 0.0;          // sqrt(sum over pairs and channels of weight * residual^2 / 3): an RMS
  double relativeError = 0.0;  // error over the same RMS of the target alone
  double seconds = 0.0;        // CPU seconds of its search and all its starts
  int iterations = 0;          // of the best start
  int starts = 0;              // LM solves run
  int failedStarts = 0;        // LM solves that ended without a usable solution (not counted as fitted)
  // Why the fit should not be trusted as it stands: a term the data clearly shows that the fit left at zero, a
  // parameter the data does not constrain. Empty for a clean fit.
  std::vector<std::string> warnings;
};

// The models fitted by default: every model of the library with a density that is not read from a file (not delta,
// not measured); a test-tree model (tests/models) is fitted only when named.
// The models a fit tries when it names none; with byName also those fitted only when named (`fit: by name`).
std::vector<std::string> fittableModels(bool byName = false);
// "4 LM starts per model, lafortune 16": the starts a fit with these options gives each model, for messages.
std::string describeStarts(const FitOptions& options);
// "search of 256 points per model, gltf_pbr 1024": the search's size, with the models whose registry multiplies it.
std::string describeSearch(const FitOptions& options);

// Fits and ranks: best (least error) first. Throws Error for an unknown or unfittable model name.
std::vector<FitResult> fitModels(const FitTarget& target, const FitOptions& options);

// A fit's parameters by name, each with one value or three (RGB), in its model's order: the JSON of `raylab brdf
// fit` and Python's table.
std::vector<std::pair<std::string, std::vector<double>>> fitParams(const FitResult& fit);
// "rho_d=0.1/0.2/0.3,rho_s=0.5,alpha_x=0.12": the parameter list `--material` and `--compare` take.
std::string fitParamList(const FitResult& fit);

// The error of a material against the target (FitResult::error, relativeError).
double fitError(const FitTarget& target, const gpu::MaterialRecord& record, FitMetric metric,
                double* relativeError = nullptr);

}  // namespace raylab
