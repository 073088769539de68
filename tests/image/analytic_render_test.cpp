// Whole renders against closed-form radiance: a Lambert sphere under a point light is
// L = rho/pi * I cos(theta) / r^2 at every lit pixel; shadowed pixels are exactly 0; and the same settings
// give a bit-identical image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>

#include "render/renderer.h"
#include "render/gpu_scene.h"
#include "builtin_scenes/default_scene.h"
#include "scene/shapes.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class AnalyticRenderTest : public GpuTest {};

struct SphereSetup {
  glm::dvec3 center;
  double radius;
  glm::dvec3 rho;
  glm::dvec3 lightPosition;
  glm::dvec3 intensity;
};

Scene makeSphereScene(const SphereSetup& s, glm::vec3 cameraPosition) {
  Scene scene;
  scene.name = "analytic sphere";
  scene.materials.push_back({"lambert", lambertMaterial(glm::vec3(s.rho))});
  scene.spheres.push_back({glm::vec3(s.center), static_cast<float>(s.radius), 0});
  scene.lights.push_back({"point", pointLight(glm::vec3(s.lightPosition), glm::vec3(s.intensity))});
  scene.camera.position = cameraPosition;
  scene.camera.target = glm::vec3(s.center);
  scene.camera.yfov = glm::radians(30.0f);
  return scene;
}

// Compares every clearly lit pixel of the sphere with the closed form, within 1e-4 relative plus the effect
// of an absolute error `cosTolerance` in cos(theta); returns how many pixels were compared.
int expectAnalyticSphere(const Image& image, const gpu::FrameParams& params, const SphereSetup& s,
                         double cosTolerance) {
  int compared = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      double missDistance = 0.0;
      const std::optional<double> t = hitSphere(ray, s.center, s.radius, &missDistance);
      const glm::vec4 pixel = image.at(x, y);
      // Pixels whose centre ray grazes the silhouette may fall either way in float32.
      if (std::abs(missDistance - s.radius) < 1e-4 * s.radius) continue;
      if (!t) {
        EXPECT_EQ(pixel.r, 0.0f) << "background pixel " << x << "," << y;
        continue;
      }
      const glm::dvec3 p = ray.origin + *t * ray.direction;
      const glm::dvec3 n = (p - s.center) / s.radius;
      const glm::dvec3 toLight = s.lightPosition - p;
      const double r2 = glm::dot(toLight, toLight);
      const double cosTheta = glm::dot(n, toLight) / std::sqrt(r2);
      // Near the terminator cos(theta) is tiny and float32 positions move it by more than 1e-4 relative.
      if (std::abs(cosTheta) < 1e-2) continue;
      const glm::dvec3 expected = cosTheta > 0.0 ? s.rho / kPi * s.intensity * cosTheta / r2 : glm::dvec3(0.0);
      for (int c = 0; c < 3; ++c) {
        if (expected[c] == 0.0) {
          EXPECT_EQ(pixel[c], 0.0f) << "unlit pixel " << x << "," << y;
        } else {
          const double perCos = s.rho[c] / kPi * s.intensity[c] / r2;
          EXPECT_NEAR(pixel[c], expected[c], 1e-4 * expected[c] + cosTolerance * perCos)
              << "pixel " << x << "," << y << " channel " << c;
        }
      }
      ++compared;
    }
  }
  return compared;
}

TEST_F(AnalyticRenderTest, LambertSphereUnderPointLightMatchesClosedForm) {
  const SphereSetup setup{{0.0, 0.0, 0.0}, 1.0, {0.8, 0.5, 0.2}, {2.0, 3.0, 4.0}, {10.0, 20.0, 30.0}};
  const Scene scene = makeSphereScene(setup, {0.0f, 0.5f, 4.0f});
  const RenderSettings settings = pixelCentres(96, 72);
  const Image image = renderImage(device(), scene, settings, 1);
  const gpu::FrameParams params = frameFor(scene, settings.width, settings.height);
  EXPECT_GT(expectAnalyticSphere(image, params, setup, 0.0), 1500);
}

TEST_F(AnalyticRenderTest, FarFromTheOriginTheRayOffsetStillAvoidsSelfShadowing) {
  // At 2e4 units a float32 ulp is 2e-3: any fixed epsilon below that self-shadows (pixels of 0), one above
  // it leaks. Positions themselves are only good to that ulp, which tilts the normal of a radius-2 sphere by
  // up to ~1e-3 rad, so cos(theta) is allowed 2e-3 of absolute error: far tighter than acne, which is 100%.
  const SphereSetup setup{{1.0e4, -2.0e4, 5.0e3}, 2.0, {0.6, 0.6, 0.6}, {1.0e4 + 3.0, -2.0e4 + 6.0, 5.0e3 + 8.0},
                          {50.0, 50.0, 50.0}};
  const Scene scene = makeSphereScene(setup, glm::vec3(setup.center) + glm::vec3(1.0f, 2.0f, 9.0f));
  const RenderSettings settings = pixelCentres(64, 64);
  const Image image = renderImage(device(), scene, settings, 1);
  const gpu::FrameParams params = frameFor(scene, settings.width, settings.height);
  EXPECT_GT(expectAnalyticSphere(image, params, setup, 2e-3), 800);
}

TEST_F(AnalyticRenderTest, ShadowedGroundIsExactlyZeroAndLitGroundMatchesClosedForm) {
  // A sphere above a ground plane, the light straight above it: the ground under the sphere is in shadow.
  Scene scene;
  scene.materials.push_back({"ground", lambertMaterial(glm::vec3(0.5f))});
  scene.materials.push_back({"sphere", lambertMaterial(glm::vec3(0.5f))});
  scene.meshes.push_back(makeGroundPlane(10.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.spheres.push_back({{0.0f, 1.5f, 0.0f}, 0.5f, 1});
  scene.lights.push_back({"above", pointLight({0.0f, 4.0f, 0.0f}, glm::vec3(16.0f))});
  scene.camera.position = {0.0f, 6.0f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(40.0f);

  const RenderSettings settings = pixelCentres(80, 60);
  const Image image = renderImage(device(), scene, settings, 1);
  const gpu::FrameParams params = frameFor(scene, settings.width, settings.height);

  int shadowed = 0, lit = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      double missDistance = 0.0;
      if (hitSphere(ray, {0.0, 1.5, 0.0}, 0.5, &missDistance) || missDistance < 0.51) continue;  // the sphere
      const double t = -ray.origin.y / ray.direction.y;
      const glm::dvec3 p = ray.origin + t * ray.direction;
      // The shadow of the sphere: the ray from p to the light passes within 0.5 of the centre.
      const Ray toLight{p, glm::normalize(glm::dvec3(0.0, 4.0, 0.0) - p)};
      double lightMiss = 0.0;
      const bool blocked = hitSphere(toLight, {0.0, 1.5, 0.0}, 0.5, &lightMiss).has_value();
      if (std::abs(lightMiss - 0.5) < 0.02) continue;  // the penumbra-free edge, either way in float32
      const float value = image.at(x, y).r;
      if (blocked) {
        EXPECT_EQ(value, 0.0f) << "shadowed pixel " << x << "," << y;
        ++shadowed;
      } else {
        const glm::dvec3 d = glm::dvec3(0.0, 4.0, 0.0) - p;
        const double r2 = glm::dot(d, d);
        const double expected = 0.5 / kPi * 16.0 * (d.y / std::sqrt(r2)) / r2;
        EXPECT_NEAR(value, expected, 1e-4 * expected) << "lit pixel " << x << "," << y;
        ++lit;
      }
    }
  }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 1000);
}

TEST_F(AnalyticRenderTest, SameSettingsGiveABitIdenticalImage) {
  const Scene scene = makeDefaultScene();
  RenderSettings settings;
  settings.width = 64;
  settings.height = 36;
  settings.seed = 7;
  const Image first = renderImage(device(), scene, settings, 4);
  const Image second = renderImage(device(), scene, settings, 4);
  ASSERT_EQ(first.rgba.size(), second.rgba.size());
  EXPECT_EQ(std::memcmp(first.rgba.data(), second.rgba.data(), first.rgba.size() * sizeof(float)), 0);

  // And the seed matters: another seed jitters differently.
  settings.seed = 8;
  const Image other = renderImage(device(), scene, settings, 4);
  EXPECT_NE(std::memcmp(first.rgba.data(), other.rgba.data(), first.rgba.size() * sizeof(float)), 0);
}

TEST_F(AnalyticRenderTest, TheImageDoesNotDependOnHowSamplesAreBatched) {
  // renderSamples(4) puts all four samples in one dispatch at this size; four calls of one sample each use
  // four dispatches and four submissions. The viewer and `raylab render` batch differently: same image.
  const Scene scene = makeDefaultScene();
  RenderSettings settings;
  settings.width = 40;
  settings.height = 24;
  const Image batched = renderImage(device(), scene, settings, 4);
  GpuScene gpuScene = uploadScene(device(), scene);
  Renderer renderer = createRenderer(device(), gpuScene, scene, settings);
  for (int i = 0; i < 4; ++i) renderSamples(device(), renderer, 1);
  const Image oneByOne = readImage(device(), renderer);
  destroyRenderer(device(), renderer);
  destroyGpuScene(device(), gpuScene);
  ASSERT_EQ(batched.rgba.size(), oneByOne.rgba.size());
  EXPECT_EQ(std::memcmp(batched.rgba.data(), oneByOne.rgba.data(), batched.rgba.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace raylab::test
