#include "bench/ray_sets.h"

#include <bit>
#include <cmath>
#include <random>

#include "scene/camera_frame.h"

namespace raylab {

glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n) {
  constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
  glm::vec3 result;
  for (int i = 0; i < 3; ++i) {
    const auto offset = static_cast<std::int32_t>(kIntScale * n[i]);
    const float moved = std::bit_cast<float>(std::bit_cast<std::int32_t>(p[i]) + (p[i] < 0.0f ? -offset : offset));
    result[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : moved;
  }
  return result;
}

std::vector<gpu::ProbeRay> primaryRays(const Scene& scene, std::uint32_t width, std::uint32_t height) {
  gpu::FrameParams params{};
  params.width = width;
  params.height = height;
  applyCamera(params, scene.camera, width, height);
  std::vector<gpu::ProbeRay> rays;
  rays.reserve(std::size_t(width) * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      rays.push_back({params.cameraOrigin, 0.0f, primaryDirection(params, {x, y}), 1e30f});
    }
  }
  return rays;
}

namespace {

glm::vec3 facingNormal(const gpu::ProbeHit& hit, const gpu::ProbeRay& ray) {
  return glm::dot(hit.geometricNormal, ray.direction) < 0.0f ? hit.geometricNormal : -hit.geometricNormal;
}

}  // namespace

std::vector<gpu::ProbeRay> shadowRays(std::span<const gpu::ProbeHit> hits, std::span<const gpu::ProbeRay> rays,
                                      glm::vec3 lightPosition) {
  std::vector<gpu::ProbeRay> shadow;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].instance == gpu::kProbeMiss) continue;
    const glm::vec3 origin = offsetRayOrigin(hits[i].position, facingNormal(hits[i], rays[i]));
    const glm::vec3 toLight = lightPosition - origin;
    const float distance = glm::length(toLight);
    shadow.push_back({origin, 0.0f, toLight / distance, distance});
  }
  return shadow;
}

std::vector<gpu::ProbeRay> bounceRays(std::span<const gpu::ProbeHit> hits, std::span<const gpu::ProbeRay> rays) {
  std::mt19937 generator(1234);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<gpu::ProbeRay> bounce;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].instance == gpu::kProbeMiss) continue;
    const glm::vec3 n = facingNormal(hits[i], rays[i]);
    // Cosine-distributed about n (Malley): a uniform disk point lifted onto the hemisphere.
    const float r = std::sqrt(uniform(generator)), phi = 6.2831853f * uniform(generator);
    const glm::vec3 helper = std::abs(n.x) > 0.5f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t = glm::normalize(glm::cross(helper, n)), b = glm::cross(n, t);
    const glm::vec3 d =
        glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n);
    bounce.push_back({offsetRayOrigin(hits[i].position, n), 0.0f, d, 1e30f});
  }
  return bounce;
}

}  // namespace raylab
