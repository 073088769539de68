#include "scene/shapes.h"

#include <cmath>

namespace raylab {

Mesh makeGroundPlane(float halfSize, float height) {
  Mesh mesh;
  mesh.name = "ground";
  mesh.positions = {{-halfSize, height, -halfSize},
                    {-halfSize, height, halfSize},
                    {halfSize, height, halfSize},
                    {halfSize, height, -halfSize}};
  mesh.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
  mesh.uvs = {{0.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}};
  mesh.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +y
  return mesh;
}

Mesh makeBox(glm::vec3 halfExtent) {
  Mesh mesh;
  mesh.name = "box";
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = sign;
      // Two in-face directions u, v with u x v = normal, so the quad winds counter-clockwise seen from outside.
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = sign;
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      for (auto [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        mesh.positions.push_back((normal + a * u + b * v) * halfExtent);
        mesh.normals.push_back(normal);
        mesh.uvs.push_back({0.5f * (a + 1.0f), 0.5f * (b + 1.0f)});
      }
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }
  }
  return mesh;
}

Mesh makeUvSphere(glm::vec3 center, float radius, std::uint32_t rings, std::uint32_t segments) {
  Mesh mesh;
  mesh.name = "uv sphere";
  constexpr float kPi = 3.14159265358979f;
  for (std::uint32_t ring = 0; ring <= rings; ++ring) {
    const float theta = kPi * ring / rings;
    for (std::uint32_t segment = 0; segment <= segments; ++segment) {
      const float phi = 2.0f * kPi * segment / segments;
      const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      mesh.positions.push_back(center + radius * n);
      mesh.normals.push_back(n);
      mesh.uvs.push_back({float(segment) / segments, float(ring) / rings});
    }
  }
  const std::uint32_t stride = segments + 1;
  for (std::uint32_t ring = 0; ring < rings; ++ring) {
    for (std::uint32_t segment = 0; segment < segments; ++segment) {
      const std::uint32_t a = ring * stride + segment, b = a + stride;
      // The pole rows would give degenerate triangles; skip them.
      if (ring != 0) mesh.indices.insert(mesh.indices.end(), {a, b, a + 1});
      if (ring != rings - 1) mesh.indices.insert(mesh.indices.end(), {a + 1, b, b + 1});
    }
  }
  return mesh;
}

}  // namespace raylab
