#include "scene/tangents.h"

#include <cmath>

namespace raylab {

namespace {

float angleBetween(glm::vec3 a, glm::vec3 b) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f && lb > 0.0f)) return 0.0f;
  return std::acos(glm::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
}

// Any unit vector orthogonal to unit n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
glm::vec3 orthogonal(glm::vec3 n) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  return glm::vec3(1.0f + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x);
}

}  // namespace

std::vector<glm::vec4> generateTangents(const Mesh& mesh, const std::vector<glm::vec2>& uvs) {
  const std::size_t vertexCount = mesh.positions.size();
  std::vector<glm::vec3> dpdu(vertexCount, glm::vec3(0.0f)), dpdv(vertexCount, glm::vec3(0.0f));
  std::vector<glm::vec3> faceNormals(vertexCount, glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t v[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
    const glm::vec3 e1 = mesh.positions[v[1]] - mesh.positions[v[0]];
    const glm::vec3 e2 = mesh.positions[v[2]] - mesh.positions[v[0]];
    const glm::vec2 duv1 = uvs[v[1]] - uvs[v[0]];
    const glm::vec2 duv2 = uvs[v[2]] - uvs[v[0]];
    const float determinant = duv1.x * duv2.y - duv1.y * duv2.x;
    const glm::vec3 normal = glm::cross(e1, e2);
    glm::vec3 faceDpdu(0.0f), faceDpdv(0.0f);
    if (std::abs(determinant) > 1e-20f) {
      // The same gradient as the kernel's (shaders/kernel/surface.glsl), normalised so that every triangle
      // weighs by its angle alone.
      faceDpdu = (duv2.y * e1 - duv1.y * e2) / determinant;
      faceDpdv = (-duv2.x * e1 + duv1.x * e2) / determinant;
      if (glm::dot(faceDpdu, faceDpdu) > 0.0f) faceDpdu = glm::normalize(faceDpdu);
      if (glm::dot(faceDpdv, faceDpdv) > 0.0f) faceDpdv = glm::normalize(faceDpdv);
    }
    for (int corner = 0; corner < 3; ++corner) {
      const glm::vec3 p = mesh.positions[v[corner]];
      const float angle =
          angleBetween(mesh.positions[v[(corner + 1) % 3]] - p, mesh.positions[v[(corner + 2) % 3]] - p);
      dpdu[v[corner]] += angle * faceDpdu;
      dpdv[v[corner]] += angle * faceDpdv;
      faceNormals[v[corner]] += angle * (glm::dot(normal, normal) > 0.0f ? glm::normalize(normal) : normal);
    }
  }
  std::vector<glm::vec4> tangents(vertexCount);
  for (std::size_t i = 0; i < vertexCount; ++i) {
    glm::vec3 n = mesh.normals.empty() ? faceNormals[i] : mesh.normals[i];
    n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
    glm::vec3 t = dpdu[i] - glm::dot(dpdu[i], n) * n;
    const bool usable = glm::dot(t, t) > 1e-20f;
    t = usable ? glm::normalize(t) : orthogonal(n);
    const float w = usable && glm::dot(glm::cross(n, t), dpdv[i]) < 0.0f ? -1.0f : 1.0f;
    tangents[i] = glm::vec4(t, w);
  }
  return tangents;
}

}  // namespace raylab
