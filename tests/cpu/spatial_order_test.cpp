// The upload's spatial order (scene/spatial_order.h): a Hilbert curve, so consecutive primitives are neighbours,
// and a permutation that keeps every triangle, sphere and instance (the device's ids map back to the scene's).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/shapes.h"
#include "scene/spatial_order.h"

namespace raylab::test {
namespace {

// The centres of the 16^3 blocks of 64^3 cells: along the 10-bit curve each block is visited whole, and consecutive
// blocks share a face.
TEST(SpatialOrder, ConsecutiveBlocksOfTheHilbertCurveAreNeighbours) {
  std::vector<glm::vec3> points;
  for (int x = 0; x < 16; ++x) {
    for (int y = 0; y < 16; ++y) {
      for (int z = 0; z < 16; ++z) points.push_back(glm::vec3(x, y, z) * 64.0f + 32.0f);
    }
  }
  std::shuffle(points.begin(), points.end(), std::mt19937(3));
  const std::vector<std::uint32_t> order = hilbertOrder(points, glm::vec3(0.0f), glm::vec3(1024.0f));
  ASSERT_EQ(order.size(), points.size());
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i) << "not a permutation";
  for (std::size_t k = 1; k < order.size(); ++k) {
    const glm::vec3 step = glm::abs(points[order[k]] - points[order[k - 1]]);
    EXPECT_EQ(step.x + step.y + step.z, 64.0f) << "a jump at " << k;
  }
}

TEST(SpatialOrder, TheGeometryIsAPermutationOfTheScenes) {
  Scene scene;
  scene.meshes.push_back(makeUvSphere(glm::vec3(0.0f), 1.0f, 12, 16));
  std::mt19937 random(5);
  std::vector<std::uint32_t> shuffled;
  Mesh& mesh = scene.meshes[0];
  std::vector<std::uint32_t> order(mesh.indices.size() / 3);
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), random);
  for (std::uint32_t t : order) shuffled.insert(shuffled.end(), &mesh.indices[3 * t], &mesh.indices[3 * t] + 3);
  mesh.indices = shuffled;
  for (int i = 0; i < 20; ++i) scene.spheres.push_back({glm::vec3(float(i % 5), float(i / 5), 0.0f), 0.3f, 0});
  for (int i = 0; i < 10; ++i) {
    scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(float(9 - i) * 3.0f, 0.0f, 0.0f)), 0});
  }
  const OrderedGeometry geometry = spatiallyOrderedGeometry(scene);
  const Mesh& ordered = geometry.scene.meshes[0];
  ASSERT_EQ(ordered.indices.size(), mesh.indices.size());
  for (std::size_t k = 0; k < geometry.triangles[0].size(); ++k) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(ordered.indices[3 * k + c], mesh.indices[3 * geometry.triangles[0][k] + c]);
  }
  for (std::size_t k = 0; k < geometry.spheres.size(); ++k) {
    EXPECT_EQ(geometry.scene.spheres[k].center, scene.spheres[geometry.spheres[k]].center);
  }
  std::vector<std::uint32_t> instances = geometry.instances;
  std::sort(instances.begin(), instances.end());
  for (std::uint32_t i = 0; i < instances.size(); ++i) EXPECT_EQ(instances[i], i) << "instances: not a permutation";
  for (std::size_t k = 0; k < geometry.instances.size(); ++k) {
    EXPECT_EQ(geometry.scene.instances[k].transform, scene.instances[geometry.instances[k]].transform);
  }
  const OrderedGeometry kept = spatiallyOrderedGeometry(scene, false);
  EXPECT_EQ(kept.scene.meshes[0].indices, mesh.indices) << "the submitted order, for measuring";
}

}  // namespace
}  // namespace raylab::test
