// Tangents for normal maps on meshes that bring none (glTF 3.7.2.1: "client implementations SHOULD calculate
// tangents using default MikkTSpace algorithms"). Each vertex gets the angle-weighted sum of the UV gradients
// dp/du of its triangles, as MikkTSpace weights them, made orthogonal to the vertex normal, and w = +1 or -1 as
// the summed dp/dv lies on the side of cross(normal, tangent) or not. MikkTSpace also splits a vertex that
// mirrored UV islands share; here such a vertex keeps one tangent (docs/gltf.md).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// One tangent per vertex of `mesh` from the UV set `uvs` (one per vertex). A vertex whose triangles have no
// usable UV gradient (degenerate UVs) gets any unit vector orthogonal to its normal, w = +1.
std::vector<glm::vec4> generateTangents(const Mesh& mesh, const std::vector<glm::vec2>& uvs);

}  // namespace raylab
