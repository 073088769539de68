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
// lavapipe compile a scene's kernel for 40 s. A unit's seven vec4s hold its first-layer weights and its row of the
// second layer's, packed so that no load is spent on padding; the tail holds the rest.
vec3 nbrdfNetwork(uint block, float x[kNbrdfInputs]) {
  const uint at = block / 4u;
  const vec4 xa = vec4(x[0], x[1], x[2], x[3]);
  vec4 second[6] = vec4[6](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
  [[dont_unroll]] for (uint i = 0u; i < kNbrdfHidden; ++i) {
    const uint unit = at + kNbrdfUnits4 + kNbrdfUnitVec4s * i;
    const vec4 last = brdfTables4[unit + 6u];  // (W2[i][20], W1[4][i], W1[5][i], b1[i])
    const float first = max(dot(xa, brdfTables4[unit]) + x[4] * last.y + x[5] * last.z + last.w, 0.0);
    [[unroll]] for (uint q = 0u; q < 5u; ++q) second[q] += first * brdfTables4[unit + 1u + q];
    second[5].x += first * last.x;
  }
  vec4 tail[kNbrdfTailVec4s];
  [[unroll]] for (uint k = 0u; k < kNbrdfTailVec4s; ++k) tail[k] = brdfTables4[at + kNbrdfTail4 + k];
  const uint w3 = kNbrdfHidden, b3 = kNbrdfHidden + kNbrdfHidden * kNbrdfOutputs;  // floats into the tail
  vec3 y = vec3(tail[b3 / 4u][b3 % 4u], tail[(b3 + 1u) / 4u][(b3 + 1u) % 4u], tail[(b3 + 2u) / 4u][(b3 + 2u) % 4u]);
  [[unroll]] for (uint j = 0u; j < kNbrdfHidden; ++j) {
    const float a = max(second[j / 4u][j % 4u] + tail[j / 4u][j % 4u], 0.0);  // + b2[j]
    const uint w = w3 + kNbrdfOutputs * j;
    y += a * vec3(tail[w / 4u][w % 4u], tail[(w + 1u) / 4u][(w + 1u) % 4u], tail[(w + 2u) / 4u][(w + 2u) % 4u]);
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
  // eight Cook-Torrance materials: 2.53x without the turns, 2.43x with them; docs/performance.md). Subgroup
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
