// The point a glTF camera orbits and zooms about. A glTF camera has a position and a direction but no
// target; the viewer needs one on the scene, or a 20-degree orbit slides the scene out of frame.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// The first triangle or sphere of `scene` along the unit `direction` from `origin`: its distance and material.
// A plain CPU ray cast over every triangle, in double precision: for a loaded camera's pivot and for the
// viewer's picking (a click), not per pixel. Rays pass through the holes of alpha-masked surfaces and the fully
// transparent parts of blended ones, as the kernels' rays do.
struct SceneHit {
  float distance = 0.0f;
  std::uint32_t material = 0;
};
std::optional<SceneHit> firstHit(const Scene& scene, glm::vec3 origin, glm::vec3 direction);
std::optional<float> firstHitDistance(const Scene& scene, glm::vec3 origin, glm::vec3 direction);

// The axis-aligned box around every triangle and sphere (world space); both corners 0 for an empty scene.
struct SceneBounds {
  glm::vec3 low{0.0f};
  glm::vec3 high{0.0f};
};
SceneBounds sceneBounds(const Scene& scene);

// Where the camera's view ray meets the scene; when it meets nothing, the point of the view ray nearest to
// the centre of the scene's bounds (at least a small distance ahead).
glm::vec3 orbitPivot(const Scene& scene, glm::vec3 position, glm::vec3 direction);

}  // namespace raylab
