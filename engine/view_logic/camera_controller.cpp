#include "view_logic/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace raylab {

namespace {

constexpr float kPoleMargin = glm::radians(2.0f);  // the view stays this far from straight up or down
constexpr float kOrbitRadiansPerPixel = 0.005f;
constexpr float kLookRadiansPerPixel = 0.003f;
constexpr float kZoomPerWheelStep = 0.9f;
constexpr float kFlyScenesPerSecond = 0.15f;  // fly speed in scene diagonals per second
constexpr float kFastFlyFactor = 4.0f;         // shift held

glm::vec3 rotate(glm::vec3 v, float angle, glm::vec3 axis) {
  return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

// Limits `pitch`, an angle by which `direction` turns towards `up`, so that it ends kPoleMargin or more away
// from both poles.
float clampPitch(glm::vec3 direction, glm::vec3 up, float pitch) {
  const float polar = std::acos(std::clamp(glm::dot(glm::normalize(direction), glm::normalize(up)), -1.0f, 1.0f));
  return std::clamp(pitch, polar - glm::pi<float>() + kPoleMargin, polar - kPoleMargin);
}

glm::vec3 rightOf(const Camera& camera) {
  return glm::normalize(glm::cross(camera.target - camera.position, camera.up));
}

}  // namespace

void orbitCamera(Camera& camera, float yaw, float pitch) {
  glm::vec3 offset = camera.position - camera.target;
  const glm::vec3 right = rightOf(camera);
  // The offset turns towards up (the camera rises) when rotated about `right` by a negative angle.
  pitch = clampPitch(offset, camera.up, pitch);
  offset = rotate(offset, -pitch, right);
  offset = rotate(offset, yaw, camera.up);
  camera.position = camera.target + offset;
}

void panCamera(Camera& camera, float dx, float dy) {
  const glm::vec3 forward = camera.target - camera.position;
  const float viewHeight = 2.0f * glm::length(forward) * std::tan(0.5f * camera.yfov);
  const glm::vec3 right = rightOf(camera);
  const glm::vec3 up = glm::normalize(glm::cross(right, forward));
  const glm::vec3 shift = viewHeight * (dx * right + dy * up);
  camera.position += shift;
  camera.target += shift;
}

void zoomCamera(Camera& camera, float factor, float minDistance) {
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  const float next = std::max(distance * factor, minDistance);
  camera.position = camera.target + offset * (next / distance);
}

void lookCamera(Camera& camera, float yaw, float pitch) {
  glm::vec3 forward = camera.target - camera.position;
  const glm::vec3 right = rightOf(camera);
  pitch = clampPitch(forward, camera.up, pitch);
  forward = rotate(forward, pitch, right);  // positive: looks up
  forward = rotate(forward, yaw, camera.up);
  camera.target = camera.position + forward;
}

void flyCamera(Camera& camera, glm::vec3 move) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = rightOf(camera);
  const glm::vec3 up = glm::normalize(glm::cross(right, forward));
  const glm::vec3 shift = move.x * right + move.y * up + move.z * forward;
  camera.position += shift;
  camera.target += shift;
}

float sceneSize(const Scene& scene) {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(-std::numeric_limits<float>::max());
  for (const MeshInstance& instance : scene.instances) {
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
      const glm::vec3 world = glm::vec3(instance.transform * glm::vec4(p, 1.0f));
      lo = glm::min(lo, world);
      hi = glm::max(hi, world);
    }
  }
  for (const Sphere& sphere : scene.spheres) {
    lo = glm::min(lo, sphere.center - sphere.radius);
    hi = glm::max(hi, sphere.center + sphere.radius);
  }
  const float fromBounds = hi.x >= lo.x ? glm::length(hi - lo) : 0.0f;
  const float fromCamera = glm::length(scene.camera.target - scene.camera.position);
  return std::max({fromBounds, fromCamera, 1.0e-3f});
}

CameraController makeCameraController(const Scene& scene) {
  CameraController controller;
  controller.home = scene.camera;
  controller.sceneSize = sceneSize(scene);
  return controller;
}

bool updateCamera(const CameraController& controller, Camera& camera, const CameraInput& input, bool mouseFree,
                  bool keyboardFree, double seconds) {
  const glm::vec2 delta = input.cursorDelta;
  const float height = std::max(input.viewHeight, 1.0f);
  bool moved = false;
  if (mouseFree && delta != glm::vec2(0.0f)) {
    if ((input.left && input.shift) || input.middle) {
      panCamera(camera, -delta.x / height, delta.y / height);
      moved = true;
    } else if (input.left) {
      orbitCamera(camera, -delta.x * kOrbitRadiansPerPixel, delta.y * kOrbitRadiansPerPixel);
      moved = true;
    } else if (input.right) {
      lookCamera(camera, -delta.x * kLookRadiansPerPixel, -delta.y * kLookRadiansPerPixel);
      moved = true;
    }
  }
  if (mouseFree && input.scroll != 0.0) {
    zoomCamera(camera, std::pow(kZoomPerWheelStep, float(input.scroll)), 1.0e-4f * controller.sceneSize);
    moved = true;
  }
  // Fly: WASD/QE while the right button is held, as in most 3D tools.
  if (keyboardFree && input.right && input.fly != glm::vec3(0.0f)) {
    const float speed = kFlyScenesPerSecond * controller.sceneSize * (input.shift ? kFastFlyFactor : 1.0f);
    flyCamera(camera, glm::normalize(input.fly) * speed * float(std::min(seconds, 0.25)));
    moved = true;
  }
  if (keyboardFree && input.reset) {
    camera = controller.home;
    moved = true;
  }
  return moved;
}

}  // namespace raylab
