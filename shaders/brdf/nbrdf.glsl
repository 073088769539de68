// Neural BRDF: Sztrajman, Rainer, Ritschel & Weyrich, "Neural BRDF Representation and Importance Sampling", CGF
// 2021. A measured material as a 6 -> 21 -> 21 -> 3 network (ReLU, ReLU, linear, then exp(x) - 1), read from the
// published Keras files (engine/measured/nbrdf.h, docs/brdfs.md, "nbrdf"). Input: the half vector with phi_h = 0,
// (sin theta_h, 0, cos theta_h), and Rusinkiewicz's difference vector d folded to phi_d in [0, pi).
// lobes: reflection glossy
// | parameter | range          | default | kind    | meaning                                                 |
// |-----------|----------------|---------|---------|---------------------------------------------------------|
// | file      | [0, 16777215]  | 0       | network | the network's .h5 file (its .json beside it), a path     |
// Sampling: the tabulated half-vector sampler of `measured`, built from the network at load (measured_sampling.h).
#ifndef RAYLAB_BRDF_NBRDF_GLSL
#define RAYLAB_BRDF_NBRDF_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "brdf/common.glsl"
#include "brdf/half_vector_table.glsl"

vec3 nbrdfEval(float file, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);
  float sinH, cosH;
  vec3 d = merlDifferenceVector(wi, wo, sinH, cosH);
  if (d.y < 0.0) d.xy = -d.xy;  // phi_d + pi -> phi_d: the half the networks learned, and reciprocity exactly
  const float x[kNbrdfInputs] = float[kNbrdfInputs](sinH, 0.0, cosH, d.x, d.y, d.z);
  // Each layer's kernel is row-major (inputs x outputs), its bias after it (shared/brdf_tables.h). The first layer's
  // units are visited in a loop that is not unrolled, each adding its share to the second layer's 21 sums: every
  // array is then indexed by constants only and lives in registers, and the kernel stays small. Unrolled whole,
  // the network made lavapipe compile a scene's kernel for 40 s.
  const uint w1 = fileBlock(file) + kNbrdfWeights;
  const uint b1 = w1 + kNbrdfInputs * kNbrdfHidden;
  const uint w2 = b1 + kNbrdfHidden;
  const uint b2 = w2 + kNbrdfHidden * kNbrdfHidden;
  const uint w3 = b2 + kNbrdfHidden;
  const uint b3 = w3 + kNbrdfHidden * kNbrdfOutputs;
  float second[kNbrdfHidden];
  [[unroll]] for (uint j = 0u; j < kNbrdfHidden; ++j) second[j] = brdfTables[b2 + j];
  [[dont_unroll]] for (uint i = 0u; i < kNbrdfHidden; ++i) {
    float first = brdfTables[b1 + i];
    [[unroll]] for (uint k = 0u; k < kNbrdfInputs; ++k) first += x[k] * brdfTables[w1 + k * kNbrdfHidden + i];
    first = max(first, 0.0);
    [[unroll]] for (uint j = 0u; j < kNbrdfHidden; ++j) second[j] += first * brdfTables[w2 + i * kNbrdfHidden + j];
  }
  vec3 y = vec3(brdfTables[b3], brdfTables[b3 + 1u], brdfTables[b3 + 2u]);
  [[unroll]] for (uint j = 0u; j < kNbrdfHidden; ++j) {
    y += max(second[j], 0.0) * vec3(brdfTables[w3 + j * kNbrdfOutputs], brdfTables[w3 + j * kNbrdfOutputs + 1u],
                                    brdfTables[w3 + j * kNbrdfOutputs + 2u]);
  }
  // exp(y) - 1 reaches down to -1; a BRDF is not negative (the authors' renderer clamps too).
  return max(vec3(expm1Accurate(y.x), expm1Accurate(y.y), expm1Accurate(y.z)), vec3(0.0));
}

float nbrdfPdf(float file, vec3 wi, vec3 wo) { return tablePdf(fileBlock(file) + kNbrdfSampler, wi, wo); }

BsdfSample nbrdfSample(float file, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = tableSampleDirection(fileBlock(file) + kNbrdfSampler, wo, u);
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, nbrdfEval(file, wi, wo), nbrdfPdf(file, wi, wo));
}

#endif
