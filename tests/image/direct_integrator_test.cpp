// The direct integrator (equation 2 of the slides) on scenes with known answers: a perfect mirror shows the
// radiance of what it reflects, glass with eta = 1 is invisible, total internal reflection reflects all the
// energy, a spot light's cone edge follows the documented falloff, and rough glass is lit from both sides.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "reference/brdf_reference.h"
#include "render/renderer.h"
#include "brdf_params/material_params.h"
#include "scene/shapes.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class DirectIntegratorTest : public GpuTest {};

gpu::MaterialRecord glassMaterial(float eta) {
  gpu::MaterialRecord record = defaultRecord(modelId("glass"));
  setParam(record, "eta", glm::vec3(eta), "test");
  return record;
}

TEST_F(DirectIntegratorTest, PerfectMirrorShowsTheReflectedRadiance) {
  // A mirror floor (delta = 1) under a Lambert sphere; the camera sees the sphere's reflection in the floor.
  const glm::dvec3 center(0.0, 1.5, 0.0), light(1.0, 5.0, 3.0), rho(0.7, 0.5, 0.3), intensity(30.0);
  Scene scene;
  scene.materials.push_back({"mirror", lambertMaterial(glm::vec3(0.3f), 1.0f)});
  scene.materials.push_back({"sphere", lambertMaterial(glm::vec3(rho))});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.spheres.push_back({glm::vec3(center), 1.0f, 1});
  scene.lights.push_back({"key", pointLight(glm::vec3(light), glm::vec3(intensity))});
  scene.camera.position = {0.0f, 1.0f, 6.0f};
  scene.camera.target = {0.0f, -0.5f, 0.0f};
  const Image image = renderImage(device(), scene, pixelCentres(64, 64), 1);
  const gpu::FrameParams params = frameFor(scene, 64, 64);

  int compared = 0;
  for (std::uint32_t y = 0; y < 64; ++y) {
    for (std::uint32_t x = 0; x < 64; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      double line = 0.0;
      if (hitSphere(ray, center, 1.0, &line) || std::abs(line - 1.0) < 1e-3 || ray.direction.y >= 0.0) continue;
      // The floor point, then the mirrored ray and what it sees.
      const glm::dvec3 floor = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      const Ray mirrored{floor, glm::dvec3(ray.direction.x, -ray.direction.y, ray.direction.z)};
      double mirroredLine = 0.0;
      const auto t = hitSphere(mirrored, center, 1.0, &mirroredLine);
      if (!t || std::abs(mirroredLine - 1.0) < 1e-3) continue;
      const glm::dvec3 p = mirrored.origin + *t * mirrored.direction;
      const glm::dvec3 expected = lambertRadiance(rho, p, p - center, light, intensity);
      if (expected.r <= 0.0) continue;
      // The floor point comes from barycentrics of a 40-unit quad: float32 places it within ~4e-6, which tilts
      // the reflected ray's hit on the sphere by as much; allow that in cos(theta) on top of 1e-4 relative.
      const glm::dvec3 toLight = light - p;
      const glm::dvec3 perCos = rho / kPi * intensity / glm::dot(toLight, toLight);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.at(x, y)[c], expected[c], 1e-4 * expected[c] + 2e-5 * perCos[c]) << x << "," << y;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);
}

TEST_F(DirectIntegratorTest, GlassWithEtaOneIsInvisible) {
  // A lit backdrop seen through a glass sphere. The light sits between sphere and backdrop, so the sphere's
  // shadow (glass blocks shadow rays) falls towards the camera, where nothing receives it.
  Scene without;
  without.materials.push_back({"backdrop", lambertMaterial(glm::vec3(0.8f, 0.6f, 0.4f))});
  without.materials.push_back({"glass", glassMaterial(1.0f)});
  glm::mat4 wall = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  wall[3] = glm::vec4(0.0f, 0.0f, -2.0f, 1.0f);
  without.meshes.push_back(makeGroundPlane(10.0f, 0.0f));
  without.instances.push_back({0, wall, 0});
  without.lights.push_back({"light", pointLight({0.3f, 0.2f, -0.5f}, glm::vec3(5.0f))});
  without.camera.position = {0.0f, 0.0f, 6.0f};
  without.camera.target = {0.0f, 0.0f, 0.0f};
  Scene with = without;
  with.spheres.push_back({{0.0f, 0.0f, 2.0f}, 0.8f, 1});

  const Image reference = renderImage(device(), without, pixelCentres(48, 48), 1);
  const Image glass = renderImage(device(), with, pixelCentres(48, 48), 1);
  float worst = 0.0f;
  for (std::size_t i = 0; i < reference.rgba.size(); ++i) {
    worst = std::max(worst, std::abs(glass.rgba[i] - reference.rgba[i]) / std::max(reference.rgba[i], 1e-6f));
  }
  // Rays through the sphere restart at offset origins: float tolerance, not exact equality.
  EXPECT_LT(worst, 1e-4f);
}

TEST_F(DirectIntegratorTest, TotalInternalReflectionReflectsEverything) {
  // Everything happens inside a large glass box (eta 1.5, critical angle 41.8 degrees): a camera looks up at
  // the box's top face at more than 45 degrees from its normal, so every ray reflects totally and comes down
  // onto a Lambert floor, lit by a point light, also inside. The pixel must be the floor's radiance times
  // exactly 1: a Fresnel factor below 1, a leak through the face or a lost branch would all show.
  const double top = 2.0, floorY = -1.5;
  const glm::dvec3 light(0.0, 0.5, 4.0), rho(0.6, 0.5, 0.4), intensity(20.0);
  Scene scene;
  scene.materials.push_back({"glass", glassMaterial(1.5f)});
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(rho))});
  scene.meshes.push_back(makeBox(glm::vec3(20.0f, float(top), 20.0f)));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.meshes.push_back(makeGroundPlane(15.0f, float(floorY)));
  scene.instances.push_back({1, glm::mat4(1.0f), 1});
  scene.lights.push_back({"inside", pointLight(glm::vec3(light), glm::vec3(intensity))});
  scene.camera.position = {0.0f, -1.0f, 0.0f};
  scene.camera.target = {0.0f, 0.2f, 2.0f};
  scene.camera.yfov = glm::radians(50.0f);
  const Image image = renderImage(device(), scene, pixelCentres(48, 48), 1);
  const gpu::FrameParams params = frameFor(scene, 48, 48);

  int compared = 0;
  for (std::uint32_t y = 0; y < 48; ++y) {
    for (std::uint32_t x = 0; x < 48; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      if (ray.direction.y <= 0.0 || ray.direction.y > std::cos(glm::radians(45.0))) continue;
      const glm::dvec3 atTop = ray.origin + ((top - ray.origin.y) / ray.direction.y) * ray.direction;
      const glm::dvec3 down(ray.direction.x, -ray.direction.y, ray.direction.z);
      const glm::dvec3 p = atTop + ((atTop.y - floorY) / ray.direction.y) * down;
      if (std::abs(p.x) > 14.0 || std::abs(p.z) > 14.0) continue;
      const glm::dvec3 expected = lambertRadiance(rho, p, {0.0, 1.0, 0.0}, light, intensity);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(x, y)[c], expected[c], 2e-4 * expected[c]) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 300);
}

TEST_F(DirectIntegratorTest, SpotLightConeEdgeFollowsTheDocumentedFalloff) {
  // A spot straight down onto a Lambert floor: full intensity inside the inner cone, none outside the outer
  // cone, the squared linear ramp of glTF KHR_lights_punctual in between.
  const double height = 4.0, inner = glm::radians(15.0), outer = glm::radians(25.0);
  Scene scene;
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.5f))});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  PunctualLight spot = pointLight({0.0f, float(height), 0.0f}, glm::vec3(40.0f));
  spot.type = gpu::kLightSpot;
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.cosInner = float(std::cos(inner));
  spot.cosOuter = float(std::cos(outer));
  scene.lights.push_back({"spot", spot});
  scene.camera.position = {0.0f, 9.0f, 0.01f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(30.0f);
  const Image image = renderImage(device(), scene, pixelCentres(96, 96), 1);
  const gpu::FrameParams params = frameFor(scene, 96, 96);

  int inside = 0, ramp = 0, outside = 0;
  for (std::uint32_t y = 0; y < 96; ++y) {
    for (std::uint32_t x = 0; x < 96; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      const glm::dvec3 p = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      const glm::dvec3 toLight = glm::dvec3(0.0, height, 0.0) - p;
      const double cosAngle = toLight.y / glm::length(toLight);  // angle from the spot's axis
      const double rampValue = std::clamp((cosAngle - std::cos(outer)) / (std::cos(inner) - std::cos(outer)), 0.0, 1.0);
      const double expected =
          lambertRadiance(glm::dvec3(0.5), p, {0.0, 1.0, 0.0}, {0.0, height, 0.0}, glm::dvec3(40.0)).r * rampValue *
          rampValue;
      const float value = image.at(x, y).r;
      if (cosAngle < std::cos(outer) - 1e-4) {
        EXPECT_EQ(value, 0.0f) << x << "," << y;
        ++outside;
      } else if (cosAngle > std::cos(inner) + 1e-4) {
        EXPECT_NEAR(value, expected, 1e-4 * expected) << x << "," << y;
        ++inside;
      } else if (rampValue > 0.05) {
        // In the ramp, float32 cos(angle) moves the ramp by ~1e-7 / (cos inner - cos outer).
        EXPECT_NEAR(value, expected, 1e-3 * expected) << x << "," << y;
        ++ramp;
      }
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(ramp, 100);
  EXPECT_GT(outside, 100);
}

TEST_F(DirectIntegratorTest, RoughGlassIsLitFromBothSides) {
  // A rough glass plane (ggx_dielectric, a two-sided BSDF) seen from above, with one point light above it
  // (reflection) and one below (transmission): each pixel is f(wi, wo) I |cos_i| / r^2 summed over the two
  // lights, f from the double-precision reference in the plane's frame (isotropic, so any tangent serves).
  const glm::dvec3 above(1.5, 3.0, 1.0), below(-1.0, -2.5, -0.5), intensity(20.0, 14.0, 8.0);
  gpu::MaterialRecord glass = defaultRecord(modelId("ggx_dielectric"));
  setParam(glass, "alpha_x", glm::vec3(0.3f), "test");
  setParam(glass, "alpha_y", glm::vec3(0.3f), "test");
  setParam(glass, "eta", glm::vec3(1.5f), "test");
  Scene scene;
  scene.materials.push_back({"rough glass", glass});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.lights.push_back({"above", pointLight(glm::vec3(above), glm::vec3(intensity))});
  scene.lights.push_back({"below", pointLight(glm::vec3(below), glm::vec3(intensity))});
  scene.camera.position = {0.0f, 4.0f, 5.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  const Image image = renderImage(device(), scene, pixelCentres(64, 64), 1);
  const gpu::FrameParams params = frameFor(scene, 64, 64);
  const reference::Material material = reference::fromRecord(glass);

  int compared = 0;
  double transmitted = 0.0, reflected = 0.0;
  for (std::uint32_t y = 0; y < 64; ++y) {
    for (std::uint32_t x = 0; x < 64; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      if (ray.direction.y >= -1e-3) continue;
      const glm::dvec3 p = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      // The plane's local frame: x, z in the plane, y the outward normal.
      const auto local = [](const glm::dvec3& w) { return glm::dvec3(w.x, w.z, w.y); };
      const glm::dvec3 wo = local(-ray.direction);
      glm::dvec3 expected(0.0);
      for (const glm::dvec3& light : {above, below}) {
        const glm::dvec3 toLight = light - p;
        const glm::dvec3 wi = local(glm::normalize(toLight));
        const glm::dvec3 term = reference::eval(material, wi, wo) * intensity * std::abs(wi.z) / glm::dot(toLight, toLight);
        expected += term;
        (light == above ? reflected : transmitted) += term.r;
      }
      if (expected.r < 1e-4) continue;  // far in a lobe's tail, where float32 directions dominate
      // The plane point comes from barycentrics of a 40-unit quad (float32 places it within ~4e-6), and the
      // device evaluates f in float32: 2e-3 relative.
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(x, y)[c], expected[c], 2e-3 * expected[c]) << x << "," << y;
      ++compared;
    }
  }
  std::printf("rough glass lit from both sides: %d pixels compared; light through the glass %.3g, reflected %.3g\n",
              compared, transmitted, reflected);
  EXPECT_GT(compared, 1000);
  EXPECT_GT(transmitted, 0.1 * reflected);  // both lights reach the camera
}

}  // namespace
}  // namespace raylab::test
