// The first-hit albedo and normal images the denoiser reads (kernel/aov.glsl) against their closed forms: on a
// Lambert sphere the albedo is the diffuse colour in every sample and the normal the sphere's; through glass the
// albedo is 1; with the mirror weight delta it is delta + (1 - delta) rho; where the camera ray misses, the
// background clamped to 1 and a zero normal. Both integrators, both backends and the wavefront, and the colour image
// is the same bit for bit with the images on or off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "brdf_params/material_params.h"
#include "util/error.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "shared/features.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class AovTest : public GpuTest {};

const glm::dvec3 kCenter(0.0, 0.0, 0.0);
constexpr double kRadius = 1.0;
const glm::vec3 kBackground(0.3f, 0.6f, 2.0f);  // blue above 1: the albedo clamps it

Scene sphereScene(const gpu::MaterialRecord& material) {
  Scene scene;
  scene.name = "aov sphere";
  scene.materials.push_back({"sphere", material});
  scene.spheres.push_back({glm::vec3(kCenter), static_cast<float>(kRadius), 0});
  scene.lights.push_back({"point", pointLight(glm::vec3(2.0f, 3.0f, 4.0f), glm::vec3(20.0f))});
  scene.background = kBackground;
  scene.camera.position = glm::vec3(0.0f, 0.5f, 4.0f);
  scene.camera.target = glm::vec3(kCenter);
  scene.camera.yfov = glm::radians(30.0f);
  return scene;
}

struct Rendered {
  Image image;
  std::optional<AuxiliaryImages> auxiliary;
};

Rendered render(const Device& device, const Scene& scene, RenderSettings settings, std::uint32_t integrator,
                bool aovs, std::uint32_t spp) {
  KernelFeatures kernel = featuresOf(scene);
  kernel.integrator = integrator;
  settings.kernel = kernel;
  settings.aovs = aovs;
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, spp);
  Rendered result{readImage(device, renderer), std::nullopt};
  if (aovs) result.auxiliary = readAuxiliaryImages(device, renderer);
  EXPECT_EQ(renderer.droppedSamples, 0u);
  EXPECT_EQ(hasAuxiliaryImages(renderer), aovs);
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  return result;
}

std::string label(std::uint32_t integrator, const RenderSettings& settings) {
  return std::string(integrator == gpu::kIntegratorPath ? "path" : "slides") + " on " +
         (settings.backend == Backend::kQuery ? "ray queries" : "the pipeline") +
         (settings.schedule == Schedule::kWavefront ? " as a wavefront" : "");
}

// Every pixel whose centre ray clearly hits the sphere has albedo `albedo` and the sphere's normal; every pixel that
// clearly misses it the clamped background and a zero normal. Returns how many pixels hit.
int expectClosedForms(const AuxiliaryImages& aux, const Scene& scene, glm::dvec3 albedo, const std::string& what) {
  const gpu::FrameParams params = frameFor(scene, aux.albedo.width, aux.albedo.height);
  int hits = 0;
  for (std::uint32_t y = 0; y < aux.albedo.height; ++y) {
    for (std::uint32_t x = 0; x < aux.albedo.width; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      double lineDistance = 0.0;
      const std::optional<double> t = hitSphere(ray, kCenter, kRadius, &lineDistance);
      if (std::abs(lineDistance - kRadius) < 1e-3) continue;  // the silhouette may fall either way in float32
      const glm::vec4 a = aux.albedo.at(x, y), n = aux.normal.at(x, y);
      const std::string where = what + ", pixel " + std::to_string(x) + "," + std::to_string(y);
      if (!t) {
        EXPECT_EQ(glm::vec3(a), glm::min(kBackground, glm::vec3(1.0f))) << where;
        EXPECT_EQ(glm::vec3(n), glm::vec3(0.0f)) << where;
        continue;
      }
      const glm::dvec3 normal = (ray.origin + *t * ray.direction - kCenter) / kRadius;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a[c], albedo[c], 2e-6) << where << " albedo channel " << c;
        EXPECT_NEAR(n[c], normal[c], 1e-3) << where << " normal channel " << c;
      }
      ++hits;
    }
  }
  return hits;
}

TEST_F(AovTest, ALambertSphereHasItsDiffuseColourAndNormalOnEveryIntegratorAndBackend) {
  const glm::dvec3 rho(0.8, 0.5, 0.2);
  const Scene scene = sphereScene(lambertMaterial(glm::vec3(rho)));
  for (const std::uint32_t integrator : {gpu::kIntegratorSlides, gpu::kIntegratorPath}) {
    for (const Backend backend : {Backend::kQuery, Backend::kPipeline}) {
      for (const Schedule schedule : {Schedule::kMegakernel, Schedule::kWavefront}) {
        if (schedule == Schedule::kWavefront && (integrator != gpu::kIntegratorPath || backend != Backend::kQuery)) {
          continue;
        }
        RenderSettings settings = pixelCentres(48, 36);
        settings.backend = backend;
        settings.schedule = schedule;
        const Rendered rendered = render(device(), scene, settings, integrator, true, 3);
        EXPECT_GT(expectClosedForms(*rendered.auxiliary, scene, rho, label(integrator, settings)), 300);
      }
    }
  }
}

TEST_F(AovTest, GlassIsWhiteAndTheMirrorWeightMixesAsTheSlidesShadeIt) {
  gpu::MaterialRecord glass = defaultRecord(modelId("glass"));
  const Scene glassScene = sphereScene(glass);
  const double delta = 0.25;
  const glm::dvec3 rho(0.2, 0.4, 0.6);
  const Scene mirrorScene = sphereScene(lambertMaterial(glm::vec3(rho), float(delta)));
  for (const std::uint32_t integrator : {gpu::kIntegratorSlides, gpu::kIntegratorPath}) {
    RenderSettings settings = pixelCentres(48, 36);
    const std::string what = label(integrator, settings);
    EXPECT_GT(expectClosedForms(*render(device(), glassScene, settings, integrator, true, 2).auxiliary, glassScene,
                                glm::dvec3(1.0), what + ", glass"),
              300);
    EXPECT_GT(expectClosedForms(*render(device(), mirrorScene, settings, integrator, true, 2).auxiliary, mirrorScene,
                                delta + (1.0 - delta) * rho, what + ", delta 0.25"),
              300);
  }
}

TEST_F(AovTest, TheColourImageIsTheSameBitForBitWithTheAuxiliaryImagesOnOrOff) {
  const Scene scene = sphereScene(lambertMaterial(glm::vec3(0.7f, 0.6f, 0.5f), 0.3f));
  for (const std::uint32_t integrator : {gpu::kIntegratorSlides, gpu::kIntegratorPath}) {
    RenderSettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.seed = 5;
    const Image off = render(device(), scene, settings, integrator, false, 4).image;
    const Image on = render(device(), scene, settings, integrator, true, 4).image;
    ASSERT_EQ(off.rgba.size(), on.rgba.size());
    EXPECT_EQ(std::memcmp(off.rgba.data(), on.rgba.data(), off.rgba.size() * sizeof(float)), 0)
        << label(integrator, settings);
  }
}

TEST_F(AovTest, AKernelWithoutThemRefusesToReadThem) {
  const Scene scene = sphereScene(lambertMaterial(glm::vec3(0.5f)));
  RenderSettings settings = pixelCentres(16, 16);
  GpuScene gpuScene = uploadScene(device(), scene);
  Renderer renderer = createRenderer(device(), gpuScene, scene, settings);
  EXPECT_THROW(readAuxiliaryImages(device(), renderer), Error);
  destroyRenderer(device(), renderer);
  destroyGpuScene(device(), gpuScene);
}

}  // namespace
}  // namespace raylab::test
