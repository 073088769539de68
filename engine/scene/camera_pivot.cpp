#include "scene/camera_pivot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/texture_lookup.h"

namespace raylab {

namespace {

struct TriangleHit {
  double t;
  double b1, b2;  // barycentrics of the second and third vertex
};

// Möller-Trumbore in double precision: a single ray, so accuracy costs nothing.
std::optional<TriangleHit> hitTriangle(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
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
  return t > 0.0 ? std::optional<TriangleHit>(TriangleHit{t, u, v}) : std::nullopt;
}

// Whether a hit on triangle `first` (its first index) of a mesh of `material` is seen: an alpha-masked surface
// is not where its alpha is under the cutoff, a blended one not where its alpha is 0 (the kernels' alphaPasses,
// kernel/alpha.glsl; a blended surface partly seen counts, so that a click on it picks it).
bool seenAt(const Scene& scene, const gpu::MaterialRecord& material, const Mesh& mesh, std::size_t first,
            const TriangleHit& hit) {
  if (material.textures < 0) return true;
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(material.textures)];
  if (uses.alphaMode == gpu::kAlphaOpaque) return true;
  double alpha = uses.alpha;
  const gpu::TextureRef& base = uses.refs[gpu::kTextureBaseColor];
  if (base.texture >= 0 && std::size_t(base.texture) < scene.textures.size()) {
    const auto interpolate = [&](const std::vector<glm::vec2>& set) {
      if (set.empty()) return glm::dvec2(0.0);
      const glm::dvec2 a(set[mesh.indices[first]]), b(set[mesh.indices[first + 1]]), c(set[mesh.indices[first + 2]]);
      return (1.0 - hit.b1 - hit.b2) * a + hit.b1 * b + hit.b2 * c;
    };
    const Texture& texture = scene.textures[std::size_t(base.texture)];
    alpha *= sampleTexture(texture, textureUv(base, interpolate(mesh.uvs), interpolate(mesh.uvs1)), false).a;
  }
  return uses.alphaMode == gpu::kAlphaMask ? alpha >= uses.alphaCutoff : alpha > 0.0;
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
      const std::optional<TriangleHit> hit = hitTriangle(o, d, v[0], v[1], v[2]);
      if (hit && hit->t < best && seenAt(scene, scene.materials[instance.material].record, mesh, i, *hit)) {
        best = hit->t;
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
