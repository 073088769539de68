// The BRDF library's precomputed tables, one read-only float buffer (binding kBindingBrdfTables) for every kernel
// that evaluates BRDFs. A storage buffer rather than GLSL constant arrays: lavapipe indexes a 1024-entry constant
// array so slowly that the BRDF kernels ran 8 to 40 times slower (docs/brdfs.md, "Multiple scattering").
//   [kGgxAlbedoOffset, +kGgxAlbedoSize^2)     1 - E(mu, alpha), E the directional albedo of single-scattering GGX
//                                             with F = 1, row-major: row i is alpha_i = max(0.001, i / (size - 1)),
//                                             column j is mu_j = max(1e-4, j / (size - 1))
//   [kGgxAlbedoAverageOffset, +kGgxAlbedoSize) 1 - E_avg(alpha_i), E_avg = 2 integral E(mu) mu dmu
// Stored as the energy lost, not E: float keeps 1 - E to full relative precision where E is nearly 1, and the
// compensation divides by 1 - E_avg.
// The values are computed at build time (engine/reference/ggx_albedo_table.cpp) into generated/ggx_albedo.h.
#ifndef RAYLAB_SHARED_BRDF_TABLES_H
#define RAYLAB_SHARED_BRDF_TABLES_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kGgxAlbedoSize = 32;
RL_CONST uint kGgxAlbedoOffset = 0;
RL_CONST uint kGgxAlbedoAverageOffset = kGgxAlbedoSize * kGgxAlbedoSize;
RL_CONST uint kBrdfTableFloats = kGgxAlbedoAverageOffset + kGgxAlbedoSize;

RL_NAMESPACE_END

#endif
