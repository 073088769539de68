// Neural BRDFs: Sztrajman, Rainer, Ritschel & Weyrich, "Neural BRDF Representation and Importance Sampling"
// (Computer Graphics Forum 2021). One small network per measured material, 6 -> 21 -> 21 -> 3 (ReLU, ReLU,
// linear, then exp(x) - 1), fitted to the full measurement, distributed as Keras files: `NAME.h5` (the weights,
// HDF5) and `NAME.json` (the architecture) beside it. The input is the half vector with phi_h = 0,
// (sin theta_h, 0, cos theta_h), and Rusinkiewicz's difference vector d; the output is f (RGB, per steradian,
// without the cosine) in the units of the measurement (docs/brdfs.md, "nbrdf").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace raylab {

inline constexpr int kNbrdfInputs = 6;
inline constexpr int kNbrdfHidden = 21;
inline constexpr int kNbrdfOutputs = 3;
// Each layer's kernel (inputs x outputs, row-major as Keras stores it), then its bias.
inline constexpr std::size_t kNbrdfWeights = std::size_t(kNbrdfInputs) * kNbrdfHidden + kNbrdfHidden +
                                             std::size_t(kNbrdfHidden) * kNbrdfHidden + kNbrdfHidden +
                                             std::size_t(kNbrdfHidden) * kNbrdfOutputs + kNbrdfOutputs;  // 675
// The published files are 18,736 bytes (.h5) and about 2 KB (.json); these bounds leave room for other writers.
inline constexpr std::uint64_t kMaxNbrdfWeightBytes = std::uint64_t(1) << 20;
inline constexpr std::uint64_t kMaxNbrdfArchitectureBytes = std::uint64_t(64) << 10;

struct NbrdfNetwork {
  std::array<float, kNbrdfWeights> weights{};  // in the order of kNbrdfWeights' comment, as the device reads them
};

// True for a path naming a neural BRDF (`.h5`).
bool isNbrdfPath(const std::string& path);

// Reads `path` (.h5) and the architecture beside it (.json of the same name), and checks that they are the
// published network: a Keras Sequential of Dense 6 -> 21 (relu), 21 (relu), 3 (linear) and a Lambda, whose
// weights have those shapes and are finite. Both must be regular files within their bounds. Throws Error naming
// the file and what was wrong (FileError for the file itself).
NbrdfNetwork readNbrdf(const std::string& path);
// The same checks of the files' bytes; `where` names them in errors.
NbrdfNetwork decodeNbrdf(const std::string& weightBytes, const std::string& architectureText, const std::string& where);

// Writes the network in the device's layout (shared/brdf_tables.h: vec4s of weights, 4 * gpu::kNbrdfNetwork4 floats)
// at `out`.
void writeNbrdfDeviceLayout(const NbrdfNetwork& network, float* out);

// The network's input for the pair (wi, wo): unit, in the local frame, above the horizon. The difference vector is
// folded to phi_d in [0, pi), as MERL folds it by reciprocity: the published networks were trained on phi_d over
// [0, 2 pi) from a reader that clamps phi_d >= pi to the last bin, so only this half holds the measurement, and
// folding makes f exactly reciprocal.
std::array<double, kNbrdfInputs> nbrdfInput(const glm::dvec3& wi, const glm::dvec3& wo);
// f(wi, wo), RGB, in double precision: 0 when a direction is at or below the horizon.
glm::dvec3 nbrdfEval(const NbrdfNetwork& network, const glm::dvec3& wi, const glm::dvec3& wo);

}  // namespace raylab
