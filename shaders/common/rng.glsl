// Counter-based random numbers: every value is a function of (pixel, sample index, seed, dimension), so any
// sample of any pixel can be regenerated independently and the same command gives the same image.
// The slides' integrator hashes them (pcg4d from Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT
// 9(3), 2020), as it always has, so its images stay bit-identical. The path integrator draws Owen-scrambled
// Sobol points (common/sobol.glsl) keyed by the sample index, a dimension group per call: successive samples
// of a pixel stratify each group, which lowers the noise of the first bounces.
#ifndef RAYLAB_COMMON_RNG_GLSL
#define RAYLAB_COMMON_RNG_GLSL

#include "shared/path_state.h"

#include "common/sobol.glsl"
#include "common/specialization.glsl"

uvec4 pcg4d(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}


Rng rngCreate(uvec2 pixel, uint sampleIndex, uint seed) {
  return Rng(uvec4(pixel.x | (pixel.y << 16u), sampleIndex, seed, 0u));
}

// Uniform in [0, 1): the top 24 bits as a float, so 1.0 is never returned.
float uintToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0 / 16777216.0); }

// The dimension groups of a path vertex start at 1 + kRngGroupsPerVertex * depth (group 0: the pixel jitter),
// so that each group means the same thing in every sample of a pixel whatever happened before.
const uint kRngGroupsPerVertex = 8u;
void rngStartVertex(inout Rng rng, uint depth) { rng.key.w = 1u + kRngGroupsPerVertex * depth; }

vec4 rngNext4(inout Rng rng) {
  uvec4 bits;
  if (kIntegrator == kIntegratorPath) {
    bits = sobolOwen4(rng.key.y, pcg4d(uvec4(rng.key.x, rng.key.z, rng.key.w, 0x5eed0b01u)).x);
  } else {
    bits = pcg4d(rng.key);
  }
  rng.key.w += 1u;
  return vec4(uintToUnitFloat(bits.x), uintToUnitFloat(bits.y), uintToUnitFloat(bits.z), uintToUnitFloat(bits.w));
}

vec2 rngNext2(inout Rng rng) { return rngNext4(rng).xy; }

#endif
