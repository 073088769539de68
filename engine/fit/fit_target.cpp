#include "fit/fit_target.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <random>

#include "brdf_params/material_params.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "scene/radiance_limits.h"
#include "util/error.h"
#include "util/files.h"
#include "util/number_text.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kThetaDStep = 6;
constexpr int kPhiDStep = 12;
// A CSV of samples is read whole: at most this many bytes (about 10 million samples).
constexpr std::uint64_t kMaxSampleFileBytes = std::uint64_t(1) << 30;
// The samples a CSV target may hold (docs/fitting.md): about 0.5 GiB of solver memory per thread at the cap.
constexpr std::size_t kMaxFitPairs = 1000000;

void normaliseWeights(std::vector<FitPair>& pairs) {
  double total = 0.0;
  for (const FitPair& p : pairs) total += p.weight;
  for (FitPair& p : pairs) p.weight /= total;
}

glm::dvec3 turned(const glm::dvec3& w, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * w.x - s * w.y, s * w.x + c * w.y, w.z};
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\r')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  return text;
}

}  // namespace

std::vector<FitPair> merlGridPairs(unsigned azimuthSeed) {
  const double cosMax = std::cos(kFitMaxThetaDegrees * kPi / 180.0);
  std::mt19937_64 random(azimuthSeed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<FitPair> pairs;
  std::size_t index = 0;
  for (int h = 0; h < kMerlThetaH; ++h) {
    const double u = (h + 0.5) / kMerlThetaH;
    const double thetaH = u * u * 0.5 * kPi;
    for (int d = kThetaDStep / 2; d < kMerlThetaD; d += kThetaDStep) {
      const double thetaD = (d + 0.5) / kMerlThetaD * 0.5 * kPi;
      for (int p = kPhiDStep / 2; p < kMerlPhiD; p += kPhiDStep) {
        const double phiD = (p + 0.5) / kMerlPhiD * kPi;
        FitPair pair;
        merlDirections(thetaH, thetaD, phiD, &pair.wi, &pair.wo);
        if (!(pair.wi.z > cosMax && pair.wo.z > cosMax)) continue;
        // dwi dwo = 4 cos theta_d sin theta_h sin theta_d dtheta_h dphi_h dtheta_d dphi_d, and the non-linear axis
        // gives dtheta_h = u pi du: the bins' widths in u, theta_d and phi_d are equal.
        pair.weight = 4.0 * std::cos(thetaD) * std::sin(thetaH) * std::sin(thetaD) * u;
        if (azimuthSeed != 0) {
          const double phi = 2.0 * kPi * ((index++ % 64) + uniform(random)) / 64.0;
          pair.wi = turned(pair.wi, phi);
          pair.wo = turned(pair.wo, phi);
        }
        pairs.push_back(pair);
      }
    }
  }
  normaliseWeights(pairs);
  return pairs;
}

FitTarget merlFitTarget(const std::string& path) {
  const MerlTable table = readMerl(path);
  FitTarget target;
  target.name = path;
  target.isotropic = true;
  for (FitPair pair : merlGridPairs()) {
    const std::size_t index = merlIndex(pair.wi, pair.wo);
    bool missing = false;
    for (int c = 0; c < 3; ++c) missing |= table.stored[index + c * kMerlSamples] < 0.0;
    if (missing) continue;
    pair.f = merlLookup(table, pair.wi, pair.wo);
    target.pairs.push_back(pair);
  }
  if (target.pairs.empty()) throw Error(path + ": no sample within 80 degrees of the normal is present");
  normaliseWeights(target.pairs);
  return target;
}

FitTarget sliceFitTarget(const std::string& path, SliceBin bin) {
  const MerlSlice slice = readMerlSlice(path);
  const double cosMax = std::cos(kFitMaxThetaDegrees * kPi / 180.0);
  FitTarget target;
  target.name = path;
  target.isotropic = true;
  for (int d = 0; d < kSliceThetaD; ++d) {
    for (int h = 0; h < kSliceThetaH; ++h) {
      FitPair pair;
      merlDirections(sliceThetaH(h, bin), sliceThetaD(d, bin), 0.5 * kPi, &pair.wi, &pair.wo);
      if (!(pair.wi.z > cosMax && pair.wo.z > cosMax)) continue;
      pair.f = slice.at(h, d);
      pair.weight = sliceBinMeasure(h, d);
      target.pairs.push_back(pair);
    }
  }
  normaliseWeights(target.pairs);
  return target;
}

FitTarget csvFitTarget(const std::string& path) {
  return parseFitCsv(readInputFile(path, kMaxSampleFileBytes), path);
}

FitTarget parseFitCsv(std::string_view text, const std::string& path) {
  constexpr std::string_view kHeader = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b";
  FitTarget target;
  target.name = path;
  std::size_t start = 0;
  int line = 0;
  bool header = false;
  int fields = 9;  // 10 with the weight column
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view row = trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line;
    if (line == 1 && row.starts_with("\xEF\xBB\xBF")) row.remove_prefix(3);  // a UTF-8 byte order mark
    if (row.empty() || row.front() == '#') continue;
    const std::string where = path + ":" + std::to_string(line);
    if (!header) {
      std::string compact;
      for (char c : row) {
        if (c != ' ') compact += c;
      }
      if (compact == std::string(kHeader) + ",weight") {
        fields = 10;
      } else if (compact != kHeader) {
        throw Error(where + ": expected the header '" + std::string(kHeader) + "' (optionally ',weight')", kExitUsage);
      }
      header = true;
      continue;
    }
    double v[10];
    std::size_t from = 0;
    for (int i = 0; i < fields; ++i) {
      const std::size_t comma = i < fields - 1 ? row.find(',', from) : row.size();
      if (comma == std::string_view::npos) {
        throw Error(where + ": expected " + std::to_string(fields) + " numbers separated by commas", kExitUsage);
      }
      const std::string_view field = trimmed(row.substr(from, comma - from));
      if (field.find(',') != std::string_view::npos) {
        throw Error(where + ": more than " + std::to_string(fields) + " fields", kExitUsage);
      }
      const auto [ptr, error] = std::from_chars(field.data(), field.data() + field.size(), v[i]);
      if (error != std::errc() || ptr != field.data() + field.size() || !std::isfinite(v[i])) {
        const std::string shown = field.size() > 40 ? std::string(field.substr(0, 40)) + "..." : std::string(field);
        throw Error(where + ": field " + std::to_string(i + 1) + " '" + shown + "' is not a finite number",
                    kExitUsage);
      }
      from = comma + 1;
    }
    FitPair pair;
    pair.wi = {v[0], v[1], v[2]};
    pair.wo = {v[3], v[4], v[5]};
    pair.f = {v[6], v[7], v[8]};
    for (glm::dvec3* w : {&pair.wi, &pair.wo}) {
      const double length = glm::length(*w);
      if (!(length > 1e-6 && length < 1e6)) {
        char shown[64];
        std::snprintf(shown, sizeof shown, "%.9g", length);
        throw Error(where + ": a direction of length " + shown + " (expected about 1)", kExitUsage);
      }
      *w /= length;
    }
    if (!(pair.wi.z > 0.0 && pair.wo.z > 0.0)) {
      throw Error(where + ": wi and wo must lie above the surface (z > 0)", kExitUsage);
    }
    if (pair.f.x < 0.0 || pair.f.y < 0.0 || pair.f.z < 0.0) throw Error(where + ": f is negative", kExitUsage);
    // f is bounded as radiance is (scene/radiance_limits.h), as a MERL file's samples are.
    if (std::max({pair.f.x, pair.f.y, pair.f.z}) > double(kMaxRadiance)) {
      throw Error(where + ": f above " + numberText(kMaxRadiance) + " /sr, the bound raylab keeps radiance within",
                  kExitUsage);
    }
    if (fields == 10) {
      if (v[9] < 0.0) throw Error(where + ": the weight is negative", kExitUsage);
      pair.weight = v[9];
    }
    if (target.pairs.size() == kMaxFitPairs) {
      // Refused at the first sample over, before more is parsed: each fitting thread holds a Jacobian of 3 rows per
      // pair (a million pairs of a ten-parameter model: 0.5 GiB), and a 1 GiB CSV holds ten million.
      throw Error(where + ": more than " + std::to_string(kMaxFitPairs) +
                      " samples; raylab fits at most that many (docs/fitting.md): subsample the file, weighting each "
                      "kept sample by what it stands for",
                  kExitUsage);
    }
    target.pairs.push_back(pair);
  }
  if (!header) {
    throw Error(path + ": empty; expected the header '" + std::string(kHeader) + "' and samples", kExitUsage);
  }
  if (target.pairs.empty()) throw Error(path + ": no samples after the header", kExitUsage);
  double total = 0.0;
  for (const FitPair& p : target.pairs) total += p.weight;
  if (!(total > 0.0 && std::isfinite(total))) {
    throw Error(path + (total > 0.0 ? ": the weights sum to more than a double holds; scale them down"
                                    : ": the weights sum to zero; give some sample a positive weight"),
                kExitUsage);
  }
  normaliseWeights(target.pairs);
  return target;
}

FitTarget materialFitTarget(const gpu::MaterialRecord& record, const std::string& name) {
  if (isDeltaOnly(record.model)) throw Error(name + ": a delta BSDF has no f to fit");
  const reference::Material material = reference::fromRecord(record);
  FitTarget target;
  target.name = name;
  target.pairs = merlGridPairs(20261204);
  for (FitPair& pair : target.pairs) pair.f = reference::eval(material, pair.wi, pair.wo);
  return target;
}

FitTarget loadFitTarget(const std::string& text, const std::string& fileBase) {
  // MODEL:k=v,... first: `measured:file=gold.binary` names a material, not a file.
  const std::size_t modelEnd = text.find(':');
  const bool material = modelEnd != std::string::npos && findModel(text.substr(0, modelEnd)) != nullptr;
  const std::string extension = std::filesystem::path(text).extension().string();
  if (!material && extension == ".binary") return merlFitTarget(text);
  if (!material && extension == ".slice") return sliceFitTarget(text);
  if (!material && extension == ".csv") return csvFitTarget(text);
  const std::size_t colon = text.find(':');
  const std::string modelName = text.substr(0, colon);
  const ModelInfo* model = findModel(modelName);
  if (model == nullptr) {
    throw Error("'" + text + "' is neither a MERL .binary file, a .slice, a .csv of samples, nor MODEL[:k=v,...] "
                "(models: " +
                modelNames() + ")");
  }
  gpu::MaterialRecord record = defaultRecord(model->id);
  if (colon != std::string::npos) applyParamList(record, std::string_view(text).substr(colon + 1), text, fileBase);
  checkFileParams(record, text);
  FitTarget target = materialFitTarget(record, text);
  // A measured material (a MERL table, a neural BRDF fed phi_h = 0) is isotropic by construction, as its file is.
  target.isotropic = findFileParam(*model) != nullptr;
  return target;
}

TargetSummary summarizeTarget(const FitTarget& target) {
  TargetSummary summary;
  summary.samples = target.pairs.size();
  summary.minThetaH = summary.minThetaD = 180.0;
  summary.minPositiveF = INFINITY;
  const double degrees = 180.0 / kPi;
  for (const FitPair& pair : target.pairs) {
    const glm::dvec3 h = glm::normalize(pair.wi + pair.wo);
    const double thetaH = std::acos(std::clamp(h.z, -1.0, 1.0)) * degrees;
    const double thetaD = std::acos(std::clamp(glm::dot(h, pair.wi), -1.0, 1.0)) * degrees;
    summary.maxThetaI = std::max(summary.maxThetaI, std::acos(pair.wi.z) * degrees);
    summary.maxThetaO = std::max(summary.maxThetaO, std::acos(pair.wo.z) * degrees);
    summary.minThetaH = std::min(summary.minThetaH, thetaH);
    summary.maxThetaH = std::max(summary.maxThetaH, thetaH);
    summary.minThetaD = std::min(summary.minThetaD, thetaD);
    summary.maxThetaD = std::max(summary.maxThetaD, thetaD);
    for (int c = 0; c < 3; ++c) {
      const double f = pair.f[c];
      summary.maxF = std::max(summary.maxF, f);
      if (f > 0.0) {
        summary.minPositiveF = std::min(summary.minPositiveF, f);
      } else {
        ++summary.zeroValues;
      }
    }
    summary.meanF += pair.weight * pair.f;
  }
  if (!std::isfinite(summary.minPositiveF)) summary.minPositiveF = 0.0;
  return summary;
}

std::string TargetSummary::text() const {
  char line[512];
  const double decades = minPositiveF > 0.0 ? std::log10(maxF / minPositiveF) : 0.0;
  std::snprintf(line, sizeof line,
                "%zu samples; theta_i, theta_o up to %.1f, %.1f deg; theta_h %.2f-%.1f deg, theta_d %.1f-%.1f deg; "
                "f %.3g-%.3g 1/sr (%.1f decades, %zu zero values); weighted mean f %.3g/%.3g/%.3g",
                samples, maxThetaI, maxThetaO, minThetaH, maxThetaH, minThetaD, maxThetaD, minPositiveF, maxF, decades,
                zeroValues, meanF.x, meanF.y, meanF.z);
  return line;
}

}  // namespace raylab
