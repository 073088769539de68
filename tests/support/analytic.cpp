#include "support/analytic.h"

#include <cmath>

#include "scene/camera_frame.h"

namespace raylab::test {

RenderSettings pixelCentres(std::uint32_t width, std::uint32_t height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.jitter = false;
  return settings;
}

gpu::FrameParams frameFor(const Scene& scene, std::uint32_t width, std::uint32_t height) {
  gpu::FrameParams params{};
  params.width = width;
  params.height = height;
  applyCamera(params, scene.camera, width, height);
  return params;
}

Ray pixelCenterRay(const gpu::FrameParams& params, std::uint32_t x, std::uint32_t y) {
  const double ndcX = 2.0 * (x + 0.5) / params.width - 1.0;
  const double ndcY = 1.0 - 2.0 * (y + 0.5) / params.height;
  const glm::dvec3 d = glm::dvec3(params.cameraForward) + ndcX * glm::dvec3(params.cameraRight) +
                       ndcY * glm::dvec3(params.cameraUp);
  return {glm::dvec3(params.cameraOrigin), glm::normalize(d)};
}

std::optional<double> hitSphere(const Ray& ray, glm::dvec3 center, double radius, double* lineDistance) {
  const glm::dvec3 f = ray.origin - center;
  const double b = glm::dot(f, ray.direction);
  const glm::dvec3 perpendicular = f - b * ray.direction;
  if (lineDistance != nullptr) *lineDistance = glm::length(perpendicular);
  const double discriminant = radius * radius - glm::dot(perpendicular, perpendicular);
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  if (-b - root >= 0.0) return -b - root;
  if (-b + root >= 0.0) return -b + root;
  return std::nullopt;
}

glm::dvec3 lambertRadiance(glm::dvec3 rho, glm::dvec3 p, glm::dvec3 n, glm::dvec3 lightPosition,
                           glm::dvec3 intensity) {
  const glm::dvec3 toLight = lightPosition - p;
  const double r2 = glm::dot(toLight, toLight);
  const double cosTheta = glm::dot(n, toLight) / std::sqrt(r2);
  if (cosTheta <= 0.0) return glm::dvec3(0.0);
  return rho / kPi * intensity * cosTheta / r2;
}

}  // namespace raylab::test
