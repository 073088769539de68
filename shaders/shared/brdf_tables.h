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
//   [kMeasuredOffset + b kMeasuredBlockFloats, ...) block b: one measured (MERL) file the scene uses, in the
//                                             order the upload numbers them (engine/measured/measured_library.h):
//     [kMeasuredValues, +3 kMerlSamples)      f in RGB triples at the file's sample index (scaled; missing = 0)
//     [kMeasuredPmf, +kMerlThetaH)            its sampler's theta_h bin probabilities (measured_sampling.h)
//     [kMeasuredCdf, +kMerlThetaH)            their inclusive running sum
//     [kMeasuredDensity, +kMerlThetaH + 1)    the half vector's density per unit solid angle at each bin edge
//     [kMeasuredCosineProbability]            the probability of the cosine-weighted lobe
// A material of model `measured` holds its block's number in its `file` parameter.
#ifndef RAYLAB_SHARED_BRDF_TABLES_H
#define RAYLAB_SHARED_BRDF_TABLES_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kGgxAlbedoSize = 32;
RL_CONST uint kGgxAlbedoOffset = 0;
RL_CONST uint kGgxAlbedoAverageOffset = kGgxAlbedoSize * kGgxAlbedoSize;
RL_CONST uint kBrdfTableFloats = kGgxAlbedoAverageOffset + kGgxAlbedoSize;

RL_CONST uint kMerlThetaHBins = 90;
RL_CONST uint kMerlThetaDBins = 90;
RL_CONST uint kMerlPhiDBins = 180;
RL_CONST uint kMerlSampleCount = kMerlThetaHBins * kMerlThetaDBins * kMerlPhiDBins;
RL_CONST uint kMeasuredOffset = kBrdfTableFloats;
RL_CONST uint kMeasuredValues = 0;
RL_CONST uint kMeasuredPmf = 3 * kMerlSampleCount;
RL_CONST uint kMeasuredCdf = kMeasuredPmf + kMerlThetaHBins;
RL_CONST uint kMeasuredDensity = kMeasuredCdf + kMerlThetaHBins;
RL_CONST uint kMeasuredCosineProbability = kMeasuredDensity + kMerlThetaHBins + 1;
RL_CONST uint kMeasuredBlockFloats = kMeasuredCosineProbability + 1;

RL_NAMESPACE_END

#endif
