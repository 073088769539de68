// The Vulkan core: a ray-query device is found and created, and a ray query returns the analytic distance.
#include <gtest/gtest.h>

#include <cmath>

#include "builtin_scenes/default_scene.h"
#include "scene/shapes.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class DeviceTest : public GpuTest {};

TEST_F(DeviceTest, ChosenDeviceSupportsRayQueries) {
  EXPECT_TRUE(device().report.capable());
  EXPECT_FALSE(device().report.name.empty());
  EXPECT_FALSE(device().report.driver.empty());
  EXPECT_GE(device().scratchAlignment, 1u);
  EXPECT_GE(device().report.apiVersion, VK_API_VERSION_1_2);
}

TEST_F(DeviceTest, RayQueryHitDistanceMatchesAnalyticSphereDistance) {
  Scene scene;
  scene.materials.push_back({"grey", lambertMaterial(glm::vec3(0.5f))});
  scene.spheres.push_back({{0.5f, -0.25f, -6.0f}, 1.5f, 0});

  // Straight at the centre, and off-centre at several impact parameters.
  std::vector<gpu::ProbeRay> rays;
  std::vector<double> expected;
  for (double b : {0.0, 0.3, 0.9, 1.2, 1.49}) {
    const glm::vec3 origin(0.5f + static_cast<float>(b), -0.25f, 2.0f);
    rays.push_back({origin, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f});
    const double dz = double(origin.z) - (-6.0);
    const double bx = double(origin.x) - 0.5;
    expected.push_back(dz - std::sqrt(1.5 * 1.5 - bx * bx));
  }
  rays.push_back({{3.0f, 0.0f, 2.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f});  // passes beside the sphere

  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), scene, rays);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_NE(hits[i].instance, gpu::kProbeMiss) << "ray " << i << " missed";
    EXPECT_NEAR(hits[i].t, expected[i], 1e-5 * expected[i]) << "ray " << i;
    EXPECT_EQ(hits[i].frontFace, 1u);
    // The reconstructed point lies on the sphere and the normal points out of it.
    const glm::vec3 fromCenter = hits[i].position - glm::vec3(0.5f, -0.25f, -6.0f);
    EXPECT_NEAR(glm::length(fromCenter), 1.5f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::normalize(fromCenter), hits[i].geometricNormal), 1.0f, 1e-6f);
  }
  EXPECT_EQ(hits.back().instance, gpu::kProbeMiss);
}

TEST_F(DeviceTest, TriangleHitDistanceAndTransformedInstance) {
  Scene scene;
  scene.materials.push_back({"grey", lambertMaterial(glm::vec3(0.5f))});
  scene.meshes.push_back(makeGroundPlane(1.0f, 0.0f));
  // The same plane twice: as is, and lifted to y = 2 and scaled by 3 through the instance transform.
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  glm::mat4 lifted(3.0f);
  lifted[3] = glm::vec4(10.0f, 2.0f, 0.0f, 1.0f);
  scene.instances.push_back({0, lifted, 0});

  const std::vector<gpu::ProbeRay> rays = {
      {{0.25f, 5.0f, 0.5f}, 0.0f, {0.0f, -1.0f, 0.0f}, 1e30f},   // onto the plane at y = 0
      {{12.5f, 5.0f, -2.0f}, 0.0f, {0.0f, -1.0f, 0.0f}, 1e30f},  // onto the lifted plane at y = 2
      {{0.25f, -1.0f, 0.5f}, 0.0f, {0.0f, 1.0f, 0.0f}, 1e30f},   // from below: the back face
      {{0.25f, 5.0f, 0.5f}, 0.0f, {0.0f, -1.0f, 0.0f}, 4.0f},    // tMax stops short of the plane
  };
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), scene, rays);
  EXPECT_EQ(hits[0].instance, 0u);
  EXPECT_FLOAT_EQ(hits[0].t, 5.0f);
  EXPECT_EQ(hits[0].frontFace, 1u);
  EXPECT_NEAR(hits[0].geometricNormal.y, 1.0f, 1e-6f);
  EXPECT_EQ(hits[1].instance, 1u);
  EXPECT_FLOAT_EQ(hits[1].t, 3.0f);
  EXPECT_NEAR(hits[1].position.x, 12.5f, 1e-5f);
  EXPECT_EQ(hits[2].frontFace, 0u);
  EXPECT_FLOAT_EQ(hits[2].t, 1.0f);
  EXPECT_EQ(hits[3].instance, gpu::kProbeMiss);
}

}  // namespace
}  // namespace raylab::test
