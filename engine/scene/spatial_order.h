// The scene's primitives in spatial order, before the acceleration structures are built. lavapipe 25.0.x (Debian's,
// docs/performance.md) splits primitives at the middle of the order they are submitted in, without sorting: a mesh
// whose triangles come in no spatial order (exporters, optimisers, scanners) got a tree 60 to 500 times slower than
// the same triangles in spatial order. Sorted along a Hilbert curve of their centroids, every run of consecutive
// primitives is a compact region, so the midpoint split builds a good tree whatever the file's order. (A Morton
// order, tried first, was 15-35% slower than the tessellator's own order on the 1M-triangle benchmark: its jumps
// put distant regions in one node.)
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// The order of points along the Hilbert curve through the box [low, high] (2^10 cells a side), ties by index:
// order[k] is the index of the k-th point.
std::vector<std::uint32_t> hilbertOrder(const std::vector<glm::vec3>& points, glm::vec3 low, glm::vec3 high);

// The scene's geometry with each mesh's triangles, the spheres and the mesh instances in Hilbert order, with its
// materials (and their texture uses), lights and environment strength: what the device's geometry, light records
// and primitive ids are built from. Nothing else is copied (no texture images, no environment pixels, no camera):
// the upload reads those from
// the scene itself. Primitive ids on the device are positions in this order; nothing outside the upload sees them:
// the orders map them back (the ray probe reports the scene's ids).
struct OrderedGeometry {
  Scene scene;
  std::vector<std::vector<std::uint32_t>> triangles;  // per mesh: triangles[m][k] is the scene's triangle at k
  std::vector<std::uint32_t> spheres;                 // spheres[k]: the scene's sphere at k
  std::vector<std::uint32_t> instances;               // instances[k]: the scene's mesh instance at k
};
// `sort` false keeps every order as it is (identity orders): the submitted order, for measuring.
OrderedGeometry spatiallyOrderedGeometry(const Scene& scene, bool sort = true);

}  // namespace raylab
