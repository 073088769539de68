// The phi_d = 90 degree "characteristic slice" of a MERL material (the plane BRDF Explorer shows): 90 theta_d
// rows by 90 theta_h columns of RGB float32, f in 1/sr (docs/fitting.md, "Measured slices"). Reading with every
// check a downloaded file deserves, writing (the tests make their slices from known models), and the measure of
// each bin, which weights its sample in a fit.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

inline constexpr int kSliceThetaH = 90;  // columns: theta_h = (x / 90)^2 90 degrees at a bin's start
inline constexpr int kSliceThetaD = 90;  // rows: theta_d = y degrees at a bin's start
inline constexpr std::uint64_t kSliceBytes = std::uint64_t(kSliceThetaH) * kSliceThetaD * 3 * sizeof(float);

// Where in its bin a sample's value is taken to lie. The source does not say; raylab uses the centre (each
// value stands for its whole bin, as the MERL reader's floor() indexing reads it), and tools/measured_study.py
// --bin-check measures which of the two the published fits agree with (docs/fitting.md).
enum class SliceBin { kStart, kCentre };

struct MerlSlice {
  std::vector<float> values;  // [theta_d row][theta_h column][RGB]
  glm::dvec3 at(int thetaH, int thetaD) const;
};

// Reads and checks a slice: a regular file of exactly kSliceBytes, every value a finite float in [0, 1e20] (the bound
// on radiance, scene/radiance_limits.h), not all zero.
// Throws Error (exit code 2 for the content, FileError for the file itself) naming the file and the first bad
// value by its row, column and channel.
MerlSlice readMerlSlice(const std::string& path);
MerlSlice decodeMerlSlice(const std::string& bytes, const std::string& where);
std::string encodeMerlSlice(const MerlSlice& slice);

// A bin's angles (radians) at its start or centre (theta_h along MERL's square-root axis).
double sliceThetaH(int column, SliceBin bin);
double sliceThetaD(int row, SliceBin bin);

// The bin's share of the measure dwi dwo = 4 cos theta_d sin theta_d sin theta_h dtheta_h dtheta_d (dphi_h dphi_d
// left out: the slice has one phi_d), integrated exactly over the bin. Over all bins they sum to 2.
double sliceBinMeasure(int column, int row);

}  // namespace raylab
