// Owen-scrambled Sobol points, four dimensions at a time: Burley, "Practical Hash-based Owen Scrambling",
// JCGT 9(4), 2020. The sample index is shuffled by a nested uniform scramble and each of the first four Sobol
// dimensions (direction numbers of Joe and Kuo 2008, below) is Owen-scrambled with its own seed; a different seed per
// pixel and per dimension group pads the groups together. Every point is uniform on [0, 1)^4 and groups are
// independent, so estimators stay unbiased; within one group successive sample indices stratify.
#ifndef RAYLAB_COMMON_SOBOL_GLSL
#define RAYLAB_COMMON_SOBOL_GLSL

// Laine and Karras's hash, which permutes the bits of x like an Owen scramble of its reversed bits.
uint laineKarrasPermutation(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

uint nestedUniformScramble(uint x, uint seed) {
  return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

// Burley's seed combination (a boost-style hash_combine).
uint hashCombine(uint seed, uint v) { return seed ^ (v + (seed << 6u) + (seed >> 2u)); }

// Point `index` of the shuffled, scrambled 4D Sobol sequence for `seed`, as 32-bit fractions. The direction
// numbers come from their recurrences as the bits of the index are read (dimension 0: v_i = 2^(31-i); 1: s = 1,
// m = 1; 2: s = 2, a = 1, m = 1 3; 3: s = 3, a = 1, m = 1 3 1): no table, which a CPU device would copy to the
// stack of every invocation.
// The shuffled index keeps its low kSobolIndexBits bits: bit j of a nested uniform scramble depends only on bits
// below j, so indices 0 .. 2^k - 1 map onto one aligned block of 2^k indices (whose Sobol points form a net, as
// the first 2^k do), and the loop below runs at most 20 times. raylab caps a render at 2^20 samples per pixel
// (--spp); beyond that the sequence repeats.
const uint kSobolIndexBits = 20u;

uvec4 sobolOwen4(uint index, uint seed) {
  index = nestedUniformScramble(index, seed) & ((1u << kSobolIndexBits) - 1u);
  uvec4 x = uvec4(0u);
  uint v0 = 0x80000000u, v1 = 0x80000000u;
  uvec2 v2 = uvec2(0x80000000u, 0xC0000000u);            // v_i, v_(i+1)
  uvec3 v3 = uvec3(0x80000000u, 0xC0000000u, 0x20000000u);  // v_i, v_(i+1), v_(i+2)
  for (; index != 0u; index >>= 1u) {
    if ((index & 1u) != 0u) x ^= uvec4(v0, v1, v2.x, v3.x);
    v0 >>= 1u;
    v1 ^= v1 >> 1u;
    v2 = uvec2(v2.y, v2.x ^ (v2.x >> 2u) ^ v2.y);
    v3 = uvec3(v3.y, v3.z, v3.x ^ (v3.x >> 3u) ^ v3.y);
  }
  for (uint d = 0u; d < 4u; ++d) x[d] = nestedUniformScramble(x[d], hashCombine(seed, d));
  return x;
}

#endif
