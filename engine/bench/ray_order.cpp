#include "bench/ray_order.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <random>

#include "util/bits.h"

namespace raylab {

namespace {

std::uint32_t octant(glm::vec3 d) { return (d.x < 0.0f ? 1u : 0u) | (d.y < 0.0f ? 2u : 0u) | (d.z < 0.0f ? 4u : 0u); }

}  // namespace

std::string_view rayOrderName(RayOrder order) {
  switch (order) {
    case RayOrder::kGenerated: return "generated";
    case RayOrder::kRandom: return "random";
    case RayOrder::kOctant: return "octant";
    case RayOrder::kOctantOrigin: return "octant+origin";
    case RayOrder::kOriginOctant: return "origin+octant";
    case RayOrder::kReplicated: return "8 copies";
  }
  return "?";
}

std::span<const RayOrder> allRayOrders() {
  static constexpr std::array kOrders = {RayOrder::kGenerated, RayOrder::kRandom, RayOrder::kOctant,
                                         RayOrder::kOctantOrigin, RayOrder::kOriginOctant, RayOrder::kReplicated};
  return kOrders;
}

std::vector<std::uint32_t> rayPermutation(std::span<const gpu::ProbeRay> rays, RayOrder order) {
  std::vector<std::uint32_t> permutation(rays.size());
  std::iota(permutation.begin(), permutation.end(), 0u);
  if (order == RayOrder::kGenerated) return permutation;
  if (order == RayOrder::kReplicated) {
    for (std::size_t i = 0; i < permutation.size(); ++i) permutation[i] = std::uint32_t(i / 8 * 8);
    return permutation;
  }
  if (order == RayOrder::kRandom) {
    std::mt19937 generator(20261202);
    std::shuffle(permutation.begin(), permutation.end(), generator);
    return permutation;
  }
  glm::vec3 lower(1e30f), upper(-1e30f);
  for (const gpu::ProbeRay& ray : rays) {
    lower = glm::min(lower, ray.origin);
    upper = glm::max(upper, ray.origin);
  }
  const glm::vec3 scale = 1023.0f / glm::max(upper - lower, glm::vec3(1e-20f));
  std::vector<std::uint64_t> keys(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const glm::uvec3 cell = glm::uvec3(glm::clamp((rays[i].origin - lower) * scale, glm::vec3(0.0f), glm::vec3(1023.0f)));
    const std::uint64_t morton = spreadBits(cell.x) | (spreadBits(cell.y) << 1) | (spreadBits(cell.z) << 2);
    const std::uint64_t oct = octant(rays[i].direction);
    switch (order) {
      case RayOrder::kOctant: keys[i] = oct; break;
      case RayOrder::kOctantOrigin: keys[i] = (oct << 30) | morton; break;
      default: keys[i] = (morton << 3) | oct; break;
    }
  }
  std::stable_sort(permutation.begin(), permutation.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return permutation;
}

}  // namespace raylab
