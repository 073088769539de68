#include "scene/camera_pivot.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

namespace {

// Möller-Trumbore in double precision: a single ray, so accuracy costs nothing.
std::optional<double> hitTriangle(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) / det;
  return t > 0.0 ? std::optional<double>(t) : std::nullopt;
}

std::optional<double> hitSphere(glm::dvec3 o, glm::dvec3 d, glm::dvec3 center, double radius) {
  const glm::dvec3 f = o - center;
  const double b = glm::dot(f, d);
  const double disc = radius * radius - glm::dot(f - b * d, f - b * d);
  if (disc < 0.0) return std::nullopt;
  const double root = std::sqrt(disc);
  const double near = -b - root, far = -b + root;
  if (near > 0.0) return near;
  if (far > 0.0) return far;
  return std::nullopt;
}

}  // namespace

std::optional<SceneHit> firstHit(const Scene& scene, glm::vec3 origin, glm::vec3 direction) {
  const glm::dvec3 o(origin), d(glm::normalize(direction));
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t material = 0;
  for (const MeshInstance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    const glm::dmat4 m(instance.transform);
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      glm::dvec3 v[3];
      for (int k = 0; k < 3; ++k) v[k] = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + k]]), 1.0));
      if (const auto t = hitTriangle(o, d, v[0], v[1], v[2]); t && *t < best) {
        best = *t;
        material = instance.material;
      }
    }
  }
  for (const Sphere& sphere : scene.spheres) {
    if (const auto t = hitSphere(o, d, glm::dvec3(sphere.center), sphere.radius); t && *t < best) {
      best = *t;
      material = sphere.material;
    }
  }
  if (!std::isfinite(best)) return std::nullopt;
  return SceneHit{float(best), material};
}

std::optional<float> firstHitDistance(const Scene& scene, glm::vec3 origin, glm::vec3 direction) {
  const std::optional<SceneHit> hit = firstHit(scene, origin, direction);
  if (!hit) return std::nullopt;
  return hit->distance;
}

SceneBounds sceneBounds(const Scene& scene) {
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  const auto add = [&](glm::vec3 p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  };
  for (const MeshInstance& instance : scene.instances) {
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions) add(glm::vec3(instance.transform * glm::vec4(p, 1.0f)));
  }
  for (const Sphere& sphere : scene.spheres) {
    add(sphere.center - sphere.radius);
    add(sphere.center + sphere.radius);
  }
  if (low.x > high.x) return {};
  return {low, high};
}

glm::vec3 orbitPivot(const Scene& scene, glm::vec3 position, glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  if (const auto t = firstHitDistance(scene, position, d)) return position + *t * d;
  const auto [low, high] = sceneBounds(scene);
  const glm::vec3 center = 0.5f * (low + high);
  const float size = std::max(glm::length(high - low), 1e-3f);
  const float along = std::max(glm::dot(center - position, d), 1e-3f * size);
  return position + along * d;
}

}  // namespace raylab
