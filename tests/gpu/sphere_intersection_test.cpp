// The analytic sphere test (intersectSphere) on the hard cases: grazing incidence, a tiny sphere far away, rays from
// inside, and AABB candidates that must lose against a nearer committed hit.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "builtin_scenes/default_scene.h"
#include "scene/shapes.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class SphereIntersectionTest : public GpuTest {};

// Nearest root >= 0 in double precision, from the float inputs the device sees; NAN on a miss.
double exactNearestT(glm::vec3 origin, glm::vec3 direction, glm::vec3 center, float radius) {
  const glm::dvec3 o(origin), d(direction), c(center);
  const double r = radius;
  const glm::dvec3 f = o - c;
  const double a = glm::dot(d, d);
  const double b = glm::dot(f, d);
  const glm::dvec3 perpendicular = f - (b / a) * d;
  const double discriminant = a * (r * r - glm::dot(perpendicular, perpendicular));
  if (discriminant < 0.0) return NAN;
  const double root = std::sqrt(discriminant);
  const double t0 = (-b - root) / a, t1 = (-b + root) / a;
  return t0 >= 0.0 ? t0 : (t1 >= 0.0 ? t1 : NAN);
}

Scene oneSphere(glm::vec3 center, float radius) {
  Scene scene;
  scene.materials.push_back({"grey", lambertMaterial(glm::vec3(0.5f))});
  scene.spheres.push_back({center, radius, 0});
  return scene;
}

TEST_F(SphereIntersectionTest, GrazingRaysHitAtTheAnalyticDistanceAndTangentNeighboursMiss) {
  const glm::vec3 center(0.0f, 0.0f, -10.0f);
  const float radius = 2.0f;
  std::vector<gpu::ProbeRay> rays;
  std::vector<double> gaps;
  // Impact parameters from r(1 - 1e-1) to r(1 - 1e-6): the cosine at the hit goes from 0.44 to 1.4e-3.
  for (int k = 1; k <= 6; ++k) {
    const double gap = std::pow(10.0, -k);
    const float b = static_cast<float>(radius * (1.0 - gap));
    rays.push_back({{b, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f});
    gaps.push_back(gap);
  }
  // Just outside the silhouette: must miss.
  for (double gap : {1e-3, 1e-5}) {
    rays.push_back({{0.0f, static_cast<float>(radius * (1.0 + gap)), 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f});
  }
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), oneSphere(center, radius), rays);
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    const double expected = exactNearestT(rays[i].origin, rays[i].direction, center, radius);
    ASSERT_NE(hits[i].instance, gpu::kProbeMiss) << "grazing ray with gap " << gaps[i] << " missed";
    // t = 10 - sqrt(r^2 - b^2): float32 leaves a few ulps of 10 in t, whatever the gap.
    EXPECT_NEAR(hits[i].t, expected, 4e-6 * 10.0) << "gap " << gaps[i];
  }
  EXPECT_EQ(hits[gaps.size()].instance, gpu::kProbeMiss);
  EXPECT_EQ(hits[gaps.size() + 1].instance, gpu::kProbeMiss);
}

TEST_F(SphereIntersectionTest, TinyDistantSphereKeepsItsPrecision) {
  // |f|^2 = 1e6 and r^2 = 1e-6: the textbook discriminant b^2 - c cancels away all twelve orders of magnitude.
  const glm::vec3 center(0.0f, 0.0f, -1000.0f);
  const float radius = 1e-3f;
  std::vector<gpu::ProbeRay> rays;
  for (float offset : {0.0f, 4e-4f, 9e-4f}) rays.push_back({{offset, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f});
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), oneSphere(center, radius), rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_NE(hits[i].instance, gpu::kProbeMiss) << "ray " << i;
    const double expected = exactNearestT(rays[i].origin, rays[i].direction, center, radius);
    // One ulp of 1000 is 6e-5: the answer must be within a few ulps, far below the radius.
    EXPECT_NEAR(hits[i].t, expected, 2.5e-4) << "ray " << i;
  }
}

TEST_F(SphereIntersectionTest, RaysFromInsideHitTheFarSideFromBehind) {
  const glm::vec3 center(1.0f, 2.0f, 3.0f);
  const float radius = 1.5f;
  std::vector<gpu::ProbeRay> rays = {
      {center, 0.0f, {0.0f, 1.0f, 0.0f}, 1e30f},
      {center, 0.0f, glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f)), 1e30f},
      {center + glm::vec3(0.0f, 0.0f, 1.2f), 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f},  // off-centre, across
      {center + glm::vec3(0.0f, 0.0f, 1.2f), 0.0f, {0.0f, 0.0f, 1.0f}, 1e30f},   // off-centre, the near wall
  };
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), oneSphere(center, radius), rays);
  const double expected[] = {1.5, 1.5, 2.7, 0.3};
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_NE(hits[i].instance, gpu::kProbeMiss) << "ray " << i;
    EXPECT_NEAR(hits[i].t, expected[i], 2e-6) << "ray " << i;
    EXPECT_EQ(hits[i].frontFace, 0u) << "ray " << i << " should see the inside";
  }
}

TEST_F(SphereIntersectionTest, NearestOfOverlappingSpheresAndTrianglesWins) {
  Scene scene = oneSphere({0.0f, 0.0f, -5.0f}, 1.0f);
  scene.spheres.push_back({{0.0f, 0.0f, -5.5f}, 1.0f, 0});  // overlaps the first, farther
  scene.spheres.push_back({{0.0f, 0.0f, -2.0f}, 0.25f, 0}); // in front of both
  scene.meshes.push_back(makeGroundPlane(5.0f, 0.0f));
  glm::mat4 wall = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  wall[3] = glm::vec4(0.0f, 0.0f, -4.5f, 1.0f);  // a wall at z = -4.5, between sphere 0's front and centre
  scene.instances.push_back({0, wall, 0});

  const std::vector<gpu::ProbeRay> rays = {
      {{0.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f},  // small sphere first: t = 1.75
      {{0.6f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, -1.0f}, 1e30f},  // big spheres' front (z = -4.2) before the wall
      {{0.6f, 0.0f, 0.0f}, 4.3f, {0.0f, 0.0f, -1.0f}, 1e30f},  // tMin past it: the wall at 4.5
  };
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), scene, rays);
  EXPECT_NEAR(hits[0].t, 1.75f, 1e-6f);
  EXPECT_NEAR(hits[1].t, 5.0 - std::sqrt(1.0 - 0.36), 2e-6);
  EXPECT_NEAR(hits[2].t, 4.5f, 1e-6f);
  EXPECT_NE(hits[2].instance, hits[1].instance);
}

}  // namespace
}  // namespace raylab::test
