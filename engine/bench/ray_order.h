// Orders of a ray set, to measure what coherence within lavapipe's 8-lane groups is worth (`raylab bench
// order`): as generated (pixel order), shuffled, grouped by direction octant, or sorted by a Morton key of origin
// and direction.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "shared/frame.h"

namespace raylab {

enum class RayOrder {
  kGenerated,     // as the rays came (bounce rays: the pixel order of their primary hits)
  kRandom,        // shuffled with a fixed seed: the order of later bounces, whose origins are scattered
  kOctant,        // stable by direction octant (3 bits)
  kOctantOrigin,  // octant, then a 30-bit Morton code of the origin within the rays' bounds
  kOriginOctant,  // the Morton code of the origin, then the octant
  kReplicated,    // every 8th ray, 8 times in a row: each group of 8 lanes traces one ray (no divergence at all)
};

std::string_view rayOrderName(RayOrder order);
std::span<const RayOrder> allRayOrders();

// The permutation that puts `rays` in `order`: rays[permutation[i]] is the i-th ray traced.
std::vector<std::uint32_t> rayPermutation(std::span<const gpu::ProbeRay> rays, RayOrder order);

template <class T>
std::vector<T> permuted(std::span<const T> items, std::span<const std::uint32_t> permutation) {
  std::vector<T> result;
  result.reserve(permutation.size());
  for (std::uint32_t i : permutation) result.push_back(items[i]);
  return result;
}

}  // namespace raylab
