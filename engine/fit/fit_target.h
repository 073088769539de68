// What `raylab brdf fit` fits to: f at a set of direction pairs with their weights, from a MERL file, a CSV of
// measured samples, or a material of the library (docs/fitting.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "fit/merl_slice.h"
#include "shared/scene_records.h"

namespace raylab {

struct FitPair {
  glm::dvec3 wi, wo;  // local frame, unit, above the horizon
  glm::dvec3 f;       // the target's f (RGB, 1/sr, without the cosine)
  double weight = 1.0;
};

struct FitTarget {
  std::string name;              // as the user gave it
  std::vector<FitPair> pairs;    // weights summing to 1
  // A MERL file or slice, or a material of a model that reads one (measured, nbrdf): anisotropy cannot be observed,
  // so by default anisotropic models are fitted with alpha_x = alpha_y (and the like); FitOptions::isotropic
  // overrides it for any target.
  bool isotropic = false;
};

// The directions above which measured data is unreliable and which the error leaves out, as Ngan et al. 2005 do.
inline constexpr double kFitMaxThetaDegrees = 80.0;

// The pairs every MERL-like target is evaluated at: the centres of the database's bins, every theta_h bin (the
// non-linear axis resolves highlights), every 6th theta_d and every 12th phi_d bin, both directions within
// kFitMaxThetaDegrees of the normal. Each is weighted by its share of the measure dwi dwo
// (= 4 cos theta_d dw_h dw_d, Rusinkiewicz 1998). `azimuthSeed` > 0 turns each pair about the normal by a
// stratified random phi_h, so that an anisotropic material is seen at every azimuth.
std::vector<FitPair> merlGridPairs(unsigned azimuthSeed = 0);

// A MERL file: its samples at merlGridPairs (missing ones left out). Throws Error naming the file.
FitTarget merlFitTarget(const std::string& path);
// A MERL phi_d = 90 slice (fit/merl_slice.h): a pair per bin at the bin's start or centre, both directions within
// kFitMaxThetaDegrees of the normal, each weighted by its bin's measure (sliceBinMeasure). Throws Error (exit code
// 2) naming the file.
FitTarget sliceFitTarget(const std::string& path, SliceBin bin = SliceBin::kCentre);
// A CSV of measured samples: header `wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b[,weight]`, one sample per line;
// equal weights without the weight column. Throws Error (exit code 2) naming the file and line.
FitTarget csvFitTarget(const std::string& path);
// The same from the file's text (`path` names it in errors).
FitTarget parseFitCsv(std::string_view text, const std::string& path);
// A material of the library, evaluated by the reference at merlGridPairs turned by random azimuths.
FitTarget materialFitTarget(const gpu::MaterialRecord& record, const std::string& name);
// TEXT as the command line gives it: a .binary file (MERL), a .slice file, a .csv file, or MODEL[:k=v,...]. A file
// parameter inside a material is relative to `fileBase`. Throws Error.
FitTarget loadFitTarget(const std::string& text, const std::string& fileBase = "");

// What a target holds, for people, before anything is fitted: samples, the angles they cover, the range of f.
struct TargetSummary {
  std::size_t samples = 0;
  double maxThetaI = 0.0, maxThetaO = 0.0;        // degrees
  double minThetaH = 0.0, maxThetaH = 0.0;        // degrees
  double minThetaD = 0.0, maxThetaD = 0.0;        // degrees
  double minPositiveF = 0.0, maxF = 0.0;          // over pairs and channels
  std::size_t zeroValues = 0;                     // pair-channels with f = 0
  glm::dvec3 meanF{0.0};                          // weighted
  std::string text() const;                       // one line
};
TargetSummary summarizeTarget(const FitTarget& target);

}  // namespace raylab
