// The point a glTF camera orbits and zooms about. A glTF camera has a position and a direction but no
// target; the viewer needs one on the scene, or a 20-degree orbit slides the scene out of frame.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// Distance along the unit `direction` from `origin` to the first triangle or sphere of `scene`, if any.
// A plain CPU ray cast over every triangle: run once per loaded camera, not per frame.
std::optional<float> firstHitDistance(const Scene& scene, glm::vec3 origin, glm::vec3 direction);

// Where the camera's view ray meets the scene; when it meets nothing, the point of the view ray nearest to
// the centre of the scene's bounds (at least a small distance ahead).
glm::vec3 orbitPivot(const Scene& scene, glm::vec3 position, glm::vec3 direction);

}  // namespace raylab
