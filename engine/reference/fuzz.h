// The fuzz layer's lobe as the kernels evaluate it (OpenPBR 1.1.1, "Fuzz"; Zeltner, Burley & Chiang 2022):
//   f_fuzz(wi, wo) cos_i = E_fuzz(mu_o, r) D(wi | wo, r),
// D a linearly transformed cosine, D(w) = w.z a^2 / (pi |M^-1 w|^4) with M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]] in
// wo's azimuthal frame, which integrates to exactly 1 over the upper hemisphere and is sampled exactly. E_fuzz, a and
// b are fitted per (mu_o, r) to the fibre volume's random walk (reference/fuzz_volume.h) and committed as a table
// (reference/fuzz_ltc_table.cpp), which the kernels read from the BRDF tables buffer.
#pragma once

#include "reference/brdf_reference.h"
#include "shared/brdf_tables.h"

namespace raylab::reference {

// The committed fit: (E_fuzz, a, b) at [3 (i kFuzzLtcSize + j) + k], roughness_i = i / (size - 1),
// mu_j = j / (size - 1) (the walks ran at 0.01 where either is 0).
extern const float kFuzzLtcTable[gpu::kFuzzLtcFloats];

struct FuzzLobe {
  double albedo = 0.0;  // E_fuzz(mu_o, r)
  double a = 1.0;
  double b = 0.0;
};
// Bilinear in the table, as the kernels read it.
FuzzLobe fuzzLobe(double mu, double roughness);

// D(wi | wo) per unit solid angle of wi; 0 below the horizon.
double fuzzDensity(const dvec3& wi, const dvec3& wo, const FuzzLobe& lobe);
// A direction drawn from D(. | wo) with u in [0, 1)^2.
dvec3 sampleFuzz(const dvec3& wo, const FuzzLobe& lobe, const dvec2& u);

}  // namespace raylab::reference
