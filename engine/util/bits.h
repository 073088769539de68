// Bit tricks shared by the spatial orders (the upload's Hilbert sort, the benchmark's Morton ray orders).
#pragma once

#include <cstdint>

namespace raylab {

// Spreads the low 10 bits of v to every third bit: interleaving three of these gives a 30-bit Morton code.
inline std::uint32_t spreadBits(std::uint32_t v) {
  v &= 0x3FFu;
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

}  // namespace raylab
