#include "gltf_read/gltf_lights.h"

#include <algorithm>
#include <cmath>

#include "scene/radiance_limits.h"
#include "util/error.h"

namespace raylab::gltf {

namespace {

constexpr double kHalfPi = 1.57079632679489661923;

}  // namespace

Light convertLight(const Document& document, int lightIndex, const glm::mat4& world, const std::string& nodeWhere) {
  const std::vector<tinygltf::Light>& lights = document.model.lights;
  if (lightIndex < 0 || std::size_t(lightIndex) >= lights.size()) {
    document.fail(nodeWhere + ": KHR_lights_punctual light " + std::to_string(lightIndex) +
                  " does not exist (the file has " + std::to_string(lights.size()) + ")");
  }
  const tinygltf::Light& gltfLight = lights[std::size_t(lightIndex)];
  const std::string where = describe("light", lightIndex, gltfLight.name) + " (at " + nodeWhere + ")";

  glm::vec3 color(1.0f);
  if (!gltfLight.color.empty()) {
    color = glm::vec3(float(gltfLight.color[0]), float(gltfLight.color[1]), float(gltfLight.color[2]));
  }
  if (!(color.r >= 0.0f && color.g >= 0.0f && color.b >= 0.0f && std::isfinite(color.r + color.g + color.b))) {
    document.fail(where + ": color must be three finite numbers >= 0");
  }
  if (!(gltfLight.intensity >= 0.0) || !std::isfinite(gltfLight.intensity)) {
    document.fail(where + ": intensity " + formatNumber(gltfLight.intensity) + " must be finite and >= 0");
  }

  Light light;
  light.name = gltfLight.name;
  PunctualLight& record = light.record;
  record.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  record.intensity = color * float(gltfLight.intensity);
  // Checked as the float the kernel uses (1e39, or 1e30 x 1e30, would reach the image as Inf).
  const double brightest = double(gltfLight.intensity) * std::max({color.r, color.g, color.b});
  if (!(brightest <= double(kMaxRadiance))) {
    document.fail(where + ": color x intensity = " + formatNumber(brightest) + " is over raylab's limit of " +
                  formatNumber(kMaxRadiance) + " (docs/scenes.md, Limits)");
  }
  record.cosInner = -1.0f;
  record.cosOuter = -1.0f;
  const glm::vec3 minusZ = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  const float length = glm::length(minusZ);
  if (gltfLight.type != "point" && !(length > 0.0f && std::isfinite(length))) {
    document.fail(where + ": the node's transform has no -Z direction to point the light along");
  }
  record.direction = gltfLight.type == "point" ? glm::vec3(0.0f, -1.0f, 0.0f) : minusZ / length;

  if (gltfLight.type == "point") {
    record.type = gpu::kLightPoint;
  } else if (gltfLight.type == "directional") {
    record.type = gpu::kLightDirectional;
  } else if (gltfLight.type == "spot") {
    record.type = gpu::kLightSpot;
    const double inner = gltfLight.spot.innerConeAngle;
    const double outer = gltfLight.spot.outerConeAngle;
    // KHR_lights_punctual: 0 <= inner < outer <= pi/2; equal angles are accepted as a hard edge.
    if (!(inner >= 0.0 && inner <= outer && outer > 0.0 && outer <= kHalfPi)) {
      document.fail(where + ": spot cone angles inner " + formatNumber(inner) + " and outer " + formatNumber(outer) +
                    " must satisfy 0 <= inner <= outer <= pi/2 and outer > 0");
    }
    record.cosInner = float(std::cos(inner));
    record.cosOuter = float(std::cos(outer));
  } else {
    document.fail(where + ": type \"" + gltfLight.type + "\" is not point, spot or directional");
  }
  if (light.name.empty()) light.name = "light " + std::to_string(lightIndex);
  return light;
}

}  // namespace raylab::gltf
