// The fuzz layer's physical reference (OpenPBR 1.1.1, "Fuzz", after Zeltner, Burley & Chiang, "Practical
// Multiple-Scattering Sheen Using Linearly Transformed Cosines", SIGGRAPH 2022 talks): a slab of unit thickness and
// unit density of white specular microflakes with the fibre-like SGGX distribution (Heitz, Dupuy, Crassin &
// Dachsbacher, "The SGGX Microflake Distribution", SIGGRAPH 2015) of fibres standing along the normal,
// S = diag(1, 1, s^2) with s = roughness^2. Its light is followed by a random walk; what leaves through the top is
// the fuzz's reflection, the rest reaches the layer below.
//
// The kernels do not walk: they read a linearly transformed cosine fitted to this walk per (mu_o, roughness)
// (reference/fuzz.h). fitFuzzLtc makes one entry of that table; tools write the whole table with
// raylab_fuzz_table (reference/fuzz_table_main.cpp), and tests compare entries with fresh walks.
#pragma once

#include <cstdint>
#include <optional>
#include <random>

#include "reference/brdf_reference.h"

namespace raylab::reference {

// The direction in which light arriving from wo (unit, wo.z > 0) leaves the slab through its top, or empty when it
// leaves through the bottom. Deterministic in `random`.
std::optional<dvec3> walkFuzzVolume(const dvec3& wo, double roughness, std::mt19937_64& random);

// One entry of the fuzz table: the slab's directional albedo at mu = wo.z and the LTC matrix
// M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]] (in wo's azimuthal frame, wo.x > 0) whose lobe best explains the
// directions the walk leaves in (maximum likelihood), from `walks` walks seeded by `seed`.
struct FuzzLtcFit {
  double albedo = 0.0;
  double a = 1.0;
  double b = 0.0;
  std::int64_t walks = 0;
  std::int64_t reflected = 0;
};
FuzzLtcFit fitFuzzLtc(double mu, double roughness, std::int64_t walks, std::uint64_t seed);

}  // namespace raylab::reference
