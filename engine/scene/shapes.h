// Procedural meshes for built-in scenes, tests and benchmarks.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace raylab {

// A square of side 2 halfSize in the y = height plane, facing +y, with UVs over [0, 1]^2.
Mesh makeGroundPlane(float halfSize, float height);

// An axis-aligned box centred at the origin, outward-facing, flat-shaded (24 vertices, 12 triangles).
Mesh makeBox(glm::vec3 halfExtent);

// A UV sphere of `rings` latitude bands and `segments` longitude segments, smooth normals.
Mesh makeUvSphere(glm::vec3 center, float radius, std::uint32_t rings, std::uint32_t segments);

}  // namespace raylab
