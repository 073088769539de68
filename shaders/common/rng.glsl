// Counter-based random numbers: every value is a hash of (pixel, sample index, seed, dimension), so any
// sample of any pixel can be regenerated independently and the same command gives the same image.
// Hash: pcg4d from Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020.
#ifndef RAYLAB_COMMON_RNG_GLSL
#define RAYLAB_COMMON_RNG_GLSL

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

struct Rng {
  uvec4 key;  // (packed pixel, sample index, seed, next dimension)
};

Rng rngCreate(uvec2 pixel, uint sampleIndex, uint seed) {
  return Rng(uvec4(pixel.x | (pixel.y << 16u), sampleIndex, seed, 0u));
}

// Uniform in [0, 1): the top 24 bits as a float, so 1.0 is never returned.
float uintToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0 / 16777216.0); }

vec4 rngNext4(inout Rng rng) {
  const uvec4 bits = pcg4d(rng.key);
  rng.key.w += 1u;
  return vec4(uintToUnitFloat(bits.x), uintToUnitFloat(bits.y), uintToUnitFloat(bits.z), uintToUnitFloat(bits.w));
}

vec2 rngNext2(inout Rng rng) { return rngNext4(rng).xy; }

#endif
