#include "fit/merl_slice.h"

#include <cmath>
#include <cstring>

#include "scene/radiance_limits.h"
#include "util/error.h"
#include "util/files.h"
#include "util/number_text.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kChannels[3] = {"red", "green", "blue"};

}  // namespace

glm::dvec3 MerlSlice::at(int thetaH, int thetaD) const {
  const float* v = &values[(std::size_t(thetaD) * kSliceThetaH + std::size_t(thetaH)) * 3];
  return {v[0], v[1], v[2]};
}

double sliceThetaH(int column, SliceBin bin) {
  const double u = (column + (bin == SliceBin::kCentre ? 0.5 : 0.0)) / kSliceThetaH;
  return u * u * 0.5 * kPi;
}

double sliceThetaD(int row, SliceBin bin) {
  return (row + (bin == SliceBin::kCentre ? 0.5 : 0.0)) / kSliceThetaD * 0.5 * kPi;
}

double sliceBinMeasure(int column, int row) {
  // int sin theta_h over [a, b] = cos a - cos b; int 4 cos sin theta_d over [c, d] = 2 (sin^2 d - sin^2 c).
  const double a = sliceThetaH(column, SliceBin::kStart), b = sliceThetaH(column + 1, SliceBin::kStart);
  const double c = sliceThetaD(row, SliceBin::kStart), d = sliceThetaD(row + 1, SliceBin::kStart);
  const double sc = std::sin(c), sd = std::sin(d);
  return (std::cos(a) - std::cos(b)) * 2.0 * (sd * sd - sc * sc);
}

MerlSlice decodeMerlSlice(const std::string& bytes, const std::string& where) {
  if (bytes.size() != kSliceBytes) {
    throw Error(where + ": holds " + std::to_string(bytes.size()) + " bytes; a phi_d = 90 slice is 90 x 90 x RGB "
                "float32, " + std::to_string(kSliceBytes) + " bytes", kExitUsage);
  }
  MerlSlice slice;
  slice.values.resize(kSliceBytes / sizeof(float));
  std::memcpy(slice.values.data(), bytes.data(), kSliceBytes);  // little-endian, as every target raylab runs on
  bool anyPositive = false;
  for (std::size_t i = 0; i < slice.values.size(); ++i) {
    const float v = slice.values[i];
    if (!std::isfinite(v) || v < 0.0f || v > kMaxRadiance) {
      const std::size_t sample = i / 3;
      throw Error(where + ": the value at theta_d row " + std::to_string(sample / kSliceThetaH) + ", theta_h column " +
                  std::to_string(sample % kSliceThetaH) + ", " + kChannels[i % 3] + " is " +
                  (std::isnan(v)   ? "NaN"
                   : std::isinf(v) ? (v > 0 ? "inf" : "-inf")
                   : v < 0.0f      ? "negative"
                                   : "above " + numberText(kMaxRadiance)) +
                  "; a slice holds finite f >= 0, at most " + numberText(kMaxRadiance) + " /sr (the bound on radiance)",
                  kExitUsage);
    }
    anyPositive |= v > 0.0f;
  }
  if (!anyPositive) throw Error(where + ": every value is zero: nothing to fit", kExitUsage);
  return slice;
}

MerlSlice readMerlSlice(const std::string& path) {
  // One byte more than a slice, so that a longer file is named as such instead of cut to size.
  return decodeMerlSlice(readInputFile(path, kSliceBytes + 1), path);
}

std::string encodeMerlSlice(const MerlSlice& slice) {
  std::string bytes(kSliceBytes, '\0');
  std::memcpy(bytes.data(), slice.values.data(), kSliceBytes);
  return bytes;
}

}  // namespace raylab
