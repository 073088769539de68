// The BRDF library's precomputed tables, one read-only float buffer (binding kBindingBrdfTables) for every kernel
// that evaluates BRDFs. A storage buffer rather than GLSL constant arrays: lavapipe indexes a 1024-entry constant
// array so slowly that the BRDF kernels ran 8 to 40 times slower (docs/brdfs.md, "Multiple scattering").
//   [kGgxAlbedoOffset, +kGgxAlbedoSize^2)     1 - E(mu, alpha), E the directional albedo of single-scattering GGX
//                                             with F = 1, row-major: row i is alpha_i = max(0.001, i / (size - 1)),
//                                             column j is mu_j = max(1e-4, j / (size - 1))
//   [kGgxAlbedoAverageOffset, +kGgxAlbedoSize) 1 - E_avg(alpha_i), E_avg = 2 integral E(mu) mu dmu
// Stored as the energy lost, not E: float keeps 1 - E to full relative precision where E is nearly 1, and the
// compensation divides by 1 - E_avg.
//   [kDielectricAlbedoOffset, +kDielectricAlbedoFloats)  1 - E_r(mu, alpha, eps), E_r the directional albedo of the
//                                             reflection of a GGX dielectric interface with the exact Fresnel term
//                                             of index (1 + eps)/(1 - eps) (openpbr's layering), at
//                                             [(k size + i) size + j]: mu_j = max(1e-4, (j / (size - 1))^2),
//                                             alpha_i = max(1e-3, (i / (size - 1))^2), eps_k = k / (eps size - 1);
//                                             its last slice (eps = 1) is GGX with F = 1 on these finer axes
//   [kMirrorAverageLossOffset, +kGgxAlbedoSize) 1 - E_avg(alpha_i) of that slice, the mean of the interpolant
//   [kAverageFresnelOffset, +kDielectricAlbedoEpsSize) 2 integral F(mu) mu dmu of the Fresnel term at eps_k
//   [kThinFilmOffset, +6 kThinFilmSamples)    the thin film's spectral integrals G_c(t), t = k kThinFilmStepNm, as
//                                             (Re, Im) of channels r, g, b per k (engine/reference/thin_film.h;
//                                             computed when the tables are made, not at build time)
//   [kFuzzLtcOffset, +kFuzzLtcFloats)         the fuzz's fitted lobe (E_fuzz, a, b) at [3 (i size + j) + k]:
//                                             roughness_i = i / (size - 1), mu_j = j / (size - 1), size kFuzzLtcSize
//                                             (engine/reference/fuzz.h; committed, written by raylab_fuzz_table)
// The values above it are computed at build time (engine/reference/ggx_albedo_table.cpp) into generated/ggx_albedo.h.
//   [kFileDirectoryOffset, +kMaxFileBlocks)   where block b begins, as the bits of a uint: the files the scene uses,
//                                             in the order the upload numbers them (engine/brdf_tables), from
//                                             kFileBlocksOffset on. A material of model `measured` or `nbrdf` holds
//                                             its block's number b in its file parameter. Two kinds of block:
//   a measured (MERL) file, kMeasuredBlockFloats:
//     [kMeasuredValues, +3 kMerlSamples)      f in RGB triples at the file's sample index (scaled; missing = 0)
//     [kMeasuredSampler, +kSamplerFloats)     its half-vector sampler
//   a neural BRDF (engine/measured/nbrdf.h), kNbrdfBlockFloats, its network in vec4s (offsets in vec4s from the
//   block's start, which is a multiple of 4 floats) so that a kernel loads four weights at a time:
//     [kNbrdfUnits4, +kNbrdfUnitVec4s kNbrdfHidden)  per first-layer unit i, seven vec4s: (W1[0..3][i]), then
//                                             W2[i][0..19] in five, then (W2[i][20], W1[4][i], W1[5][i], b1[i])
//     [kNbrdfTail4, +kNbrdfTailVec4s)         b2[0..20], W3[j][c] at 21 + 3 j + c, b3[0..2] at 84, one zero
//     [kNbrdfSampler, +kSamplerFloats)        its half-vector sampler (in floats)
//   a half-vector sampler (engine/measured/measured_sampling.h):
//     [kSamplerPmf, +kMerlThetaH)             the theta_h bins' probabilities
//     [kSamplerCdf, +kMerlThetaH)             their inclusive running sum
//     [kSamplerDensity, +kMerlThetaH + 1)     the half vector's density per unit solid angle at each bin edge
//     [kSamplerCosineProbability]             the probability of the cosine-weighted lobe
#ifndef RAYLAB_SHARED_BRDF_TABLES_H
#define RAYLAB_SHARED_BRDF_TABLES_H

#include "compat.h"

RL_NAMESPACE_BEGIN

RL_CONST uint kGgxAlbedoSize = 32;
RL_CONST uint kGgxAlbedoOffset = 0;
RL_CONST uint kGgxAlbedoAverageOffset = kGgxAlbedoSize * kGgxAlbedoSize;
RL_CONST uint kDielectricAlbedoEpsSize = 33;
RL_CONST uint kDielectricAlbedoOffset = kGgxAlbedoAverageOffset + kGgxAlbedoSize;
RL_CONST uint kDielectricAlbedoFloats = kDielectricAlbedoEpsSize * kGgxAlbedoSize * kGgxAlbedoSize;
RL_CONST uint kMirrorAverageLossOffset = kDielectricAlbedoOffset + kDielectricAlbedoFloats;
RL_CONST uint kAverageFresnelOffset = kMirrorAverageLossOffset + kGgxAlbedoSize;
RL_CONST uint kThinFilmSamples = 1024;
RL_CONST float kThinFilmStepNm = 12.5;
RL_CONST uint kThinFilmTerms = 12;
RL_CONST uint kThinFilmOffset = kAverageFresnelOffset + kDielectricAlbedoEpsSize;
RL_CONST uint kFuzzLtcSize = 32;
RL_CONST uint kFuzzLtcFloats = 3 * kFuzzLtcSize * kFuzzLtcSize;
RL_CONST uint kFuzzLtcOffset = kThinFilmOffset + 6 * kThinFilmSamples;
RL_CONST uint kBrdfTableFloats = kFuzzLtcOffset + kFuzzLtcFloats;

RL_CONST uint kMerlThetaHBins = 90;
RL_CONST uint kMerlThetaDBins = 90;
RL_CONST uint kMerlPhiDBins = 180;
RL_CONST uint kMerlSampleCount = kMerlThetaHBins * kMerlThetaDBins * kMerlPhiDBins;
RL_CONST uint kMaxFileBlocks = 64;
RL_CONST uint kFileDirectoryOffset = kBrdfTableFloats;
RL_CONST uint kFileBlocksOffset = kFileDirectoryOffset + kMaxFileBlocks;

RL_CONST uint kSamplerPmf = 0;
RL_CONST uint kSamplerCdf = kSamplerPmf + kMerlThetaHBins;
RL_CONST uint kSamplerDensity = kSamplerCdf + kMerlThetaHBins;
RL_CONST uint kSamplerCosineProbability = kSamplerDensity + kMerlThetaHBins + 1;
RL_CONST uint kSamplerFloats = kSamplerCosineProbability + 1;

RL_CONST uint kMeasuredValues = 0;
RL_CONST uint kMeasuredSampler = 3 * kMerlSampleCount;
RL_CONST uint kMeasuredBlockFloats = kMeasuredSampler + kSamplerFloats;

RL_CONST uint kNbrdfInputs = 6;
RL_CONST uint kNbrdfHidden = 21;
RL_CONST uint kNbrdfOutputs = 3;
RL_CONST uint kNbrdfUnitVec4s = 7;
RL_CONST uint kNbrdfUnits4 = 0;
RL_CONST uint kNbrdfTail4 = kNbrdfUnits4 + kNbrdfUnitVec4s * kNbrdfHidden;
RL_CONST uint kNbrdfTailVec4s = 22;  // 21 + 63 + 3 floats, and one zero
RL_CONST uint kNbrdfNetwork4 = kNbrdfTail4 + kNbrdfTailVec4s;
RL_CONST uint kNbrdfSampler = 4 * kNbrdfNetwork4;
RL_CONST uint kNbrdfBlockFloats = kNbrdfSampler + kSamplerFloats;

RL_NAMESPACE_END

#endif
