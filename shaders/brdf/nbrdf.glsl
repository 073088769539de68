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
#ifdef GL_COMPUTE_SHADER
#extension GL_KHR_shader_subgroup_ballot : require
#endif

#include "brdf/common.glsl"
#include "brdf/half_vector_table.glsl"

// The network's weights as vec4s (shared/brdf_tables.h): the same buffer as brdfTables, read four floats at a time.
// Loads, not arithmetic, were the network's cost on lavapipe (with the weights computed instead of loaded, a
// scene of eight networks cost 1.18x Cook-Torrance rather than 3.2x).
layout(set = 0, binding = kBindingBrdfTables, scalar) readonly buffer BrdfTables4 { vec4 brdfTables4[]; };

// The network of the block at `block` (a multiple of 4 floats) for input x. The first layer's units are visited in a
// loop that is not unrolled, each adding its share to the second layer's sums (six vec4s): every array is then
// indexed by constants only and lives in registers, and the kernel stays small. Unrolled whole, the network made
// lavapipe compile a scene's kernel for 40 s.
vec3 nbrdfNetwork(uint block, float x[kNbrdfInputs]) {
  const uint at = block / 4u;
  vec4 second[kNbrdfHidden4];
  [[unroll]] for (uint q = 0u; q < kNbrdfHidden4; ++q) second[q] = brdfTables4[at + kNbrdfSecondBias4 + q];
  const vec4 xa = vec4(x[0], x[1], x[2], x[3]), xb = vec4(x[4], x[5], 1.0, 0.0);  // 1: the bias's input
  [[dont_unroll]] for (uint i = 0u; i < kNbrdfHidden; ++i) {
    const uint unit = at + kNbrdfFirstLayer4 + 2u * i;
    const float first = max(dot(xa, brdfTables4[unit]) + dot(xb, brdfTables4[unit + 1u]), 0.0);
    const uint row = at + kNbrdfSecondLayer4 + kNbrdfHidden4 * i;
    [[unroll]] for (uint q = 0u; q < kNbrdfHidden4; ++q) second[q] += first * brdfTables4[row + q];
  }
  vec3 y = brdfTables4[at + kNbrdfThirdBias4].xyz;
  [[unroll]] for (uint j = 0u; j < kNbrdfHidden; ++j) {
    y += max(second[j / 4u][j % 4u], 0.0) * brdfTables4[at + kNbrdfThirdLayer4 + j].xyz;
  }
  // exp(y) - 1 reaches down to -1; a BRDF is not negative (the authors' renderer clamps too).
  return max(vec3(expm1Accurate(y.x), expm1Accurate(y.y), expm1Accurate(y.z)), vec3(0.0));
}

vec3 nbrdfEval(float file, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);
  float sinH, cosH;
  vec3 d = merlDifferenceVector(wi, wo, sinH, cosH);
  if (d.y < 0.0) d.xy = -d.xy;  // phi_d + pi -> phi_d: the half the networks learned, and reciprocity exactly
  const float x[kNbrdfInputs] = float[kNbrdfInputs](sinH, 0.0, cosH, d.x, d.y, d.z);
  const uint block = fileBlock(file);
#ifdef GL_COMPUTE_SHADER
  // The lanes of one network take turns: each turn's block is the same for every lane in it, so the driver loads
  // each weight once for them all, where a lane's own address costs one load per lane (eight networks against
  // eight Cook-Torrance materials: 2.53x without the turns, 2.23x with them; docs/performance.md). Subgroup
  // operations exist in compute kernels only (lavapipe's ray-tracing stages have none).
  for (;;) {
    const uint turn = subgroupBroadcastFirst(block);
    if (turn == block) return nbrdfNetwork(turn, x);
  }
#else
  return nbrdfNetwork(block, x);
#endif
}

float nbrdfPdf(float file, vec3 wi, vec3 wo) { return tablePdf(fileBlock(file) + kNbrdfSampler, wi, wo); }

BsdfSample nbrdfSample(float file, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = tableSampleDirection(fileBlock(file) + kNbrdfSampler, wo, u);
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, nbrdfEval(file, wi, wo), nbrdfPdf(file, wi, wo));
}

#endif
