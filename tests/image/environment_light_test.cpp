// The environment image in whole renders: camera rays see it by the documented equirectangular convention
// (rotation and strength included) in both integrators; a constant image lights a white Lambert sphere like
// the uniform background of the same radiance (the furnace, through the image's importance sampling and MIS, with
// and without path guiding);
// and under a small bright sun MIS, BSDF sampling and light sampling converge to the same image for every model.
//
// Statistics. The furnace compares the mean of (pixel - 1) over the sphere with 0 by a z-test whose standard
// error comes from the pixels' spread: |z| < 4, a false-alarm rate of 6.3e-5. The strategy comparison is a
// t-test per region over independent runs (path_test_support.h), |t| < 4.5 with 15 degrees of freedom: 4e-4
// per region, about 2.6% over the 2 x 32 regions. Seeds are fixed: a run is deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "image/path_test_support.h"
#include "render/kernel_features.h"
#include "scene/environment_tables.h"
#include "brdf_params/material_params.h"
#include "scene/shapes.h"
#include "shared/features.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class EnvironmentLightTest : public GpuTest {};

// An environment image given texel by texel.
Environment makeEnvironment(std::uint32_t width, std::uint32_t height,
                            glm::vec3 (*texel)(std::uint32_t, std::uint32_t)) {
  Environment environment;
  environment.path = "test";
  environment.width = width;
  environment.height = height;
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) environment.texels.push_back(texel(x, y));
  }
  return environment;
}

// A scene whose only geometry is a small sphere behind the camera: every camera ray escapes.
Scene emptyView(Environment environment) {
  Scene scene;
  scene.materials.push_back({"hidden", lambertMaterial(glm::vec3(0.5f))});
  scene.spheres.push_back({glm::vec3(0.0f, 0.0f, 10.0f), 0.1f, 0});
  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.target = {0.3f, 0.2f, -1.0f};
  scene.camera.yfov = glm::radians(100.0f);
  scene.environment = std::move(environment);
  return scene;
}

glm::vec3 rotateY(glm::vec3 d, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

TEST_F(EnvironmentLightTest, CameraRaysSeeTheImageByTheEquirectangularConventionInBothIntegrators) {
  // Every texel different, so that a flipped or shifted lookup cannot pass.
  Environment environment = makeEnvironment(32, 16, [](std::uint32_t x, std::uint32_t y) {
    return glm::vec3(float(x + 1), float(y + 1), float((x * 7 + y * 3) % 5 + 1));
  });
  environment.strength = 0.5f;
  environment.rotation = 0.7f;
  const Scene scene = emptyView(environment);
  constexpr std::uint32_t kSize = 48;
  const gpu::FrameParams params = frameFor(scene, kSize, kSize);
  for (std::uint32_t integrator : {gpu::kIntegratorPath, gpu::kIntegratorSlides}) {
    RenderSettings settings = pixelCentres(kSize, kSize);
    KernelFeatures kernel = featuresOf(scene);
    kernel.integrator = integrator;
    settings.kernel = kernel;
    const Image image = renderImage(device(), scene, settings, 1);
    int outside = 0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
      for (std::uint32_t x = 0; x < kSize; ++x) {
        // The kernel's float direction, atan2 and acos differ from the host's by about 1e-6 rad: the pixel must
        // be the lookup of some direction within 2e-5 rad of its ray, i.e. inside the range of the lookups at
        // the ray and at six directions that far around it (the image is smooth there but steep at the seam).
        const glm::vec3 d(pixelCenterRay(params, x, y).direction);
        glm::vec3 low(1e30f), high(-1e30f);
        for (int k = 0; k < 7; ++k) {
          glm::vec3 offset(0.0f);
          if (k > 0) offset[(k - 1) / 2] = (k % 2 ? 2e-5f : -2e-5f);
          const glm::vec3 e = rotateY(glm::normalize(d + offset), -environment.rotation);
          const glm::vec3 value = environment.strength * environmentLookup(environment, e);
          low = glm::min(low, value);
          high = glm::max(high, value);
        }
        const glm::vec3 got(image.at(x, y));
        const glm::vec3 slack = 1e-5f * high;
        if (glm::any(glm::lessThan(got, low - slack)) || glm::any(glm::greaterThan(got, high + slack))) {
          ++outside;
          ADD_FAILURE() << integratorName(integrator) << ": pixel " << x << ", " << y << " is " << got.r << ", "
                        << got.g << ", " << got.b << "; expected " << low.r << "..." << high.r << ", " << low.g
                        << "..." << high.g << ", " << low.b << "..." << high.b;
          if (outside > 5) return;
        }
      }
    }
  }
}

TEST_F(EnvironmentLightTest, ConstantImageLightsAWhiteLambertSphereToRadianceOne) {
  Scene scene = emptyView(makeEnvironment(16, 8, [](std::uint32_t, std::uint32_t) { return glm::vec3(1.0f); }));
  scene.materials[0].record = lambertMaterial(glm::vec3(1.0f));
  scene.spheres[0] = {glm::vec3(0.0f), 1.0f, 0};
  scene.camera.position = {0.0f, 0.0f, 4.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(35.0f);
  constexpr std::uint32_t kSize = 40;
  const gpu::FrameParams params = frameFor(scene, kSize, kSize);
  // MIS, light sampling alone, and MIS with path guiding, whose mixture density both MIS weights must use.
  for (int variant = 0; variant < 3; ++variant) {
    const std::uint32_t sampling = variant == 1 ? gpu::kSamplingLight : gpu::kSamplingMis;
    RenderSettings settings = samplingSettings(kSize, 0, scene, sampling);
    if (variant == 2) settings.guiding = Guiding::kOn;
    const Image image = renderImage(device(), scene, settings, 64);
    double sum = 0.0, squares = 0.0;
    int count = 0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
      for (std::uint32_t x = 0; x < kSize; ++x) {
        double line = 0.0;
        if (!hitSphere(pixelCenterRay(params, x, y), glm::dvec3(0.0), 1.0, &line) || line > 0.9) continue;
        const double d = image.at(x, y).g - 1.0;
        sum += d;
        squares += d * d;
        ++count;
      }
    }
    ASSERT_GT(count, 300);
    const double mean = sum / count;
    const double standardError = std::sqrt(std::max(squares / count - mean * mean, 1e-14) / count);
    EXPECT_LT(std::abs(mean / standardError), 4.0) << "variant " << variant << ": mean error " << mean;
  }
}

// Sky radiance 0.5 to 1 with a sun of 3 x 3 texels at 2000: radiance over more than three orders of magnitude.
glm::vec3 sunnySky(std::uint32_t x, std::uint32_t y) {
  if (x >= 40 && x < 43 && y >= 14 && y < 17) return glm::vec3(2000.0f, 1900.0f, 1700.0f);
  return glm::vec3(0.5f + 0.5f * float(y) / 64.0f, 0.6f, 1.0f - 0.4f * float(y) / 64.0f);
}

TEST_F(EnvironmentLightTest, MisBsdfAndLightSamplingAgreeUnderASmallBrightSunForEveryModel) {
  Scene scene = emptyView(makeEnvironment(128, 64, sunnySky));
  scene.materials.clear();
  scene.spheres.clear();
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.5f))});
  scene.meshes.push_back(makeGroundPlane(20.0f, -1.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  const gpu::MaterialRecord models[] = {
      material("lambert", {{"rho_d", 0.8f}}),
      material("phong", {{"rho_d", 0.3f}, {"rho_s", 0.6f}, {"s", 30.0f}}),
      material("blinnphong", {{"rho_d", 0.3f}, {"rho_s", 0.6f}, {"s", 60.0f}}),
      material("cooktorrance", {{"rho_d", 0.2f}, {"rho_s", 0.7f}, {"m", 0.2f}}),
      material("ward", {{"rho_d", 0.2f}, {"rho_s", 0.3f}, {"alpha_x", 0.1f}, {"alpha_y", 0.3f}}),
      material("ward_duer", {{"rho_d", 0.2f}, {"rho_s", 0.3f}, {"alpha_x", 0.2f}, {"alpha_y", 0.2f}}),
      material("ward_gmd", {{"rho_d", 0.2f}, {"rho_s", 0.3f}, {"alpha_x", 0.3f}, {"alpha_y", 0.1f}}),
      material("ashikhmin_shirley", {{"Rd", 0.3f}, {"Rs", 0.5f}, {"nu", 50.0f}, {"nv", 200.0f}}),
  };
  for (std::size_t i = 0; i < std::size(models); ++i) {
    scene.materials.push_back({"model" + std::to_string(i), models[i]});
    const float x = -3.0f + 2.0f * float(i % 4);
    const float y = i < 4 ? 1.1f : -0.1f;
    scene.spheres.push_back({glm::vec3(x, y, -0.5f * float(i / 4)), 0.9f, std::uint32_t(i + 1)});
  }
  scene.camera.position = {0.0f, 2.0f, 9.0f};
  scene.camera.target = {0.0f, 0.4f, 0.0f};
  scene.camera.yfov = glm::radians(40.0f);
  const RenderSettings mis = samplingSettings(64, 2, scene, gpu::kSamplingMis);
  const RenderSettings bsdf = samplingSettings(64, 2, scene, gpu::kSamplingBsdf);
  const RenderSettings light = samplingSettings(64, 2, scene, gpu::kSamplingLight);
  EXPECT_LT(worstRegionT(device(), scene, mis, bsdf, 16, 8, 8, 4), 4.5) << "MIS against BSDF sampling";
  EXPECT_LT(worstRegionT(device(), scene, mis, light, 16, 8, 8, 4), 4.5) << "MIS against light sampling";
}

}  // namespace
}  // namespace raylab::test
