#include "scene/camera_frame.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace raylab {

void applyCamera(gpu::FrameParams& params, const Camera& camera, std::uint32_t width, std::uint32_t height) {
  const glm::vec3 forward = camera.target - camera.position;
  const glm::vec3 right = glm::cross(forward, camera.up);
  if (!(glm::length(forward) > 0.0f) || !(glm::length(right) > 0.0f)) {
    throw Error("camera '" + camera.name + "': position, target and up do not define a view direction");
  }
  if (!(camera.yfov > 0.0f && camera.yfov < 3.1f)) {
    throw Error("camera '" + camera.name + "': vertical field of view " + std::to_string(camera.yfov) +
                " rad is outside (0, 3.1)");
  }
  const float tanHalf = std::tan(0.5f * camera.yfov);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::vec3 w = glm::normalize(forward);
  const glm::vec3 u = glm::normalize(right);
  const glm::vec3 v = glm::cross(u, w);
  params.cameraOrigin = camera.position;
  params.cameraForward = w;
  params.cameraRight = u * (tanHalf * aspect);
  params.cameraUp = v * tanHalf;
}

glm::vec3 primaryDirection(const gpu::FrameParams& params, glm::uvec2 pixel, glm::vec2 offset) {
  const glm::vec2 ndc(2.0f * (float(pixel.x) + offset.x) / float(params.width) - 1.0f,
                      1.0f - 2.0f * (float(pixel.y) + offset.y) / float(params.height));
  return glm::normalize(params.cameraForward + ndc.x * params.cameraRight + ndc.y * params.cameraUp);
}

}  // namespace raylab
