#include "scene/spatial_order.h"

#include <algorithm>
#include <numeric>

#include "util/bits.h"

namespace raylab {

namespace {

// Below this many primitives the order is left as the scene gives it: a tree of a few leaves is as good either way
// (the sorted order of the showcase's dozen spheres measured 6-11% slower per sample than its authored order).
constexpr std::size_t kFewPrimitives = 64;

// The position of a cell along the 3D Hilbert curve of 2^10 cells a side: Skilling's transform of the axes
// ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004), whose bits interleave into the index. Unlike a
// Morton (Z) curve, the Hilbert curve never jumps: every run of consecutive primitives is a compact region, and
// the builder's split at the middle of the count yields tight boxes.
std::uint32_t hilbertIndex(glm::uvec3 cell) {
  std::uint32_t X[3] = {cell.x, cell.y, cell.z};
  constexpr std::uint32_t M = 1u << 9;
  for (std::uint32_t Q = M; Q > 1; Q >>= 1) {
    const std::uint32_t P = Q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & Q) {
        X[0] ^= P;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & P;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t Q = M; Q > 1; Q >>= 1) {
    if (X[2] & Q) t ^= Q - 1;
  }
  for (std::uint32_t& x : X) x ^= t;
  return (spreadBits(X[0]) << 2) | (spreadBits(X[1]) << 1) | spreadBits(X[2]);
}

std::uint32_t curveIndex(glm::vec3 p, glm::vec3 low, glm::vec3 extent) {
  const glm::vec3 unit = glm::clamp((p - low) / extent, 0.0f, 1.0f);
  return hilbertIndex(glm::uvec3(glm::min(unit * 1024.0f, glm::vec3(1023.0f))));
}

}  // namespace

std::vector<std::uint32_t> hilbertOrder(const std::vector<glm::vec3>& points, glm::vec3 low, glm::vec3 high) {
  // A flat axis (a plane's thickness) must not divide by zero: any positive extent orders it the same.
  const glm::vec3 extent = glm::max(high - low, glm::vec3(1e-30f));
  std::vector<std::uint32_t> codes(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) codes[i] = curveIndex(points[i], low, extent);
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });
  return order;
}

namespace {

// Centres of a set of points with their box; non-finite points (none reach here: the loaders refuse them) would
// only land at the box's corner.
struct Centres {
  std::vector<glm::vec3> points;
  glm::vec3 low{INFINITY}, high{-INFINITY};
  void add(glm::vec3 p) {
    points.push_back(p);
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
};

Mesh orderedMesh(const Mesh& mesh, std::vector<std::uint32_t>& order, bool sort) {
  Mesh ordered = mesh;
  const std::size_t triangles = mesh.indices.size() / 3;
  order.resize(triangles);
  std::iota(order.begin(), order.end(), 0u);
  if (triangles < kFewPrimitives || !sort) return ordered;
  Centres centres;
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t* i = &mesh.indices[3 * t];
    centres.add((mesh.positions[i[0]] + mesh.positions[i[1]] + mesh.positions[i[2]]) / 3.0f);
  }
  order = hilbertOrder(centres.points, centres.low, centres.high);
  for (std::size_t k = 0; k < triangles; ++k) {
    for (int c = 0; c < 3; ++c) ordered.indices[3 * k + c] = mesh.indices[3 * order[k] + c];
  }
  return ordered;
}

}  // namespace

OrderedGeometry spatiallyOrderedGeometry(const Scene& scene, bool sort) {
  OrderedGeometry geometry;
  Scene& ordered = geometry.scene;
  // What the upload builds geometry and light records from; the images stay in the scene (see the header).
  ordered.materials = scene.materials;
  ordered.materialTextures = scene.materialTextures;
  ordered.lights = scene.lights;
  ordered.environment.strength = scene.environment.strength;
  geometry.triangles.resize(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    ordered.meshes.push_back(orderedMesh(scene.meshes[m], geometry.triangles[m], sort));
  }

  Centres spheres;
  for (const Sphere& sphere : scene.spheres) spheres.add(sphere.center);
  geometry.spheres = hilbertOrder(spheres.points, spheres.low, spheres.high);
  if (!sort || scene.spheres.size() < kFewPrimitives) std::iota(geometry.spheres.begin(), geometry.spheres.end(), 0u);
  for (std::uint32_t i : geometry.spheres) ordered.spheres.push_back(scene.spheres[i]);

  // Instances by the world centre of their mesh's box (the TLAS is split at the midpoint of this order too).
  Centres instances;
  for (const MeshInstance& instance : scene.instances) {
    glm::vec3 low(INFINITY), high(-INFINITY);
    for (const glm::vec3& p : scene.meshes.at(instance.mesh).positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
    const glm::vec3 centre = scene.meshes[instance.mesh].positions.empty() ? glm::vec3(0.0f) : 0.5f * (low + high);
    instances.add(glm::vec3(instance.transform * glm::vec4(centre, 1.0f)));
  }
  geometry.instances = hilbertOrder(instances.points, instances.low, instances.high);
  if (!sort || scene.instances.size() < kFewPrimitives) {
    std::iota(geometry.instances.begin(), geometry.instances.end(), 0u);
  }
  for (std::uint32_t i : geometry.instances) ordered.instances.push_back(scene.instances[i]);
  return geometry;
}

}  // namespace raylab
