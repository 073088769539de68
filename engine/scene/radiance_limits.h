// The one bound on what emits light, enforced wherever a value enters (glTF, --env-strength, the viewer's script
// and panel, Python): a light's intensity, an emissive surface's radiance, and an environment image's brightest
// texel times its strength are each at most kMaxRadiance. Shading multiplies these by BRDF values, 1/r^2 and
// sampling weights; 1e20 leaves that headroom within float (3.4e38), so no image becomes Inf or NaN.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace raylab {

struct Environment;

inline constexpr float kMaxRadiance = 1e20f;

// Each throws Error(where: ...) naming the value and the limit.
void checkLightIntensity(glm::vec3 intensity, const std::string& where);
// strength finite and >= 0, and strength x the image's brightest texel at most kMaxRadiance.
void checkEnvironmentStrength(const Environment& environment, float strength, const std::string& where);

}  // namespace raylab
