// Renders of a measured material agree with renders of the model it was tabulated from (issue 24), through both
// integrators: a MERL file written by raylab's own writer from Cook-Torrance, on a sphere over a floor under a
// point light and a uniform sky. Per region, a Welch t-test over independent runs of (measured - model), with a
// stated allowance for the table itself: nearest-sample lookup in bins of about 1 degree (theta_h finer near the
// highlight) moves a region's mean by well under kTableAllowance of it. |t| < 5 after the allowance: a false alarm
// rate of 4e-4 per region (t with 2 x kRuns - 2 degrees of freedom), 0.6% over the 16 regions of each integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "brdf_params/material_params.h"
#include "path_test_support.h"
#include "render/renderer.h"
#include "scene/shapes.h"
#include "shared/features.h"
#include "support/gpu_test.h"
#include "support/measured_files.h"

namespace raylab::test {
namespace {

constexpr std::uint32_t kRuns = 8, kSpp = 16, kSize = 48;
constexpr int kRegions = 4;
constexpr double kTableAllowance = 0.0025;  // relative, of a region's mean

class MeasuredRenderTest : public GpuTest {};

Scene sphereScene(const gpu::MaterialRecord& sphere) {
  Scene scene;
  scene.camera.position = {0.0f, 1.2f, 3.0f};
  scene.camera.target = {0.0f, 0.6f, 0.0f};
  scene.camera.yfov = glm::radians(35.0f);
  scene.materials.push_back({"sphere", sphere});
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.5f))});
  scene.spheres.push_back({glm::vec3(0.0f, 0.6f, 0.0f), 0.6f, 0});
  scene.meshes.push_back(makeGroundPlane(4.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 1});
  scene.lights.push_back({"key", pointLight(glm::vec3(1.5f, 3.0f, 2.0f), glm::vec3(12.0f))});
  scene.background = glm::vec3(0.3f);
  return scene;
}

std::vector<std::vector<double>> runMeans(const Device& device, const Scene& scene, std::uint32_t integrator) {
  RenderSettings settings = pathSettings(kSize, 4, scene);
  settings.kernel->integrator = integrator;
  settings.jitter = true;
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  std::vector<std::vector<double>> means;
  for (std::uint32_t run = 1; run <= kRuns; ++run) {
    renderer.params.seed = run;
    resetAccumulation(device, renderer);
    renderSamples(device, renderer, kSpp);
    means.push_back(regionMeans(readImage(device, renderer), kRegions, kRegions));
  }
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  return means;
}

// The worst region's |t| of (the measured material of test file `file` - Cook-Torrance), beyond the allowance.
double worstRegionT(const Device& device, std::uint32_t integrator, const char* name, int file) {
  const gpu::MaterialRecord model = material("cooktorrance", {{"rho_d", 0.2f}, {"rho_s", 0.8f}, {"m", 0.3f}, {"eta", 1.5f}});
  gpu::MaterialRecord measured = defaultRecord(modelId("measured"));
  // File 0 is tabulated from exactly `model` (support/measured_files.h).
  setParam(measured, "file", glm::vec3(float(measuredTestFile(file))), "test");
  const auto a = runMeans(device, sphereScene(measured), integrator);
  const auto b = runMeans(device, sphereScene(model), integrator);
  double worstT = 0.0, worstRelative = 0.0;
  for (int r = 0; r < kRegions * kRegions; ++r) {
    double meanA = 0.0, meanB = 0.0, varA = 0.0, varB = 0.0;
    for (std::uint32_t k = 0; k < kRuns; ++k) meanA += a[k][r] / kRuns, meanB += b[k][r] / kRuns;
    for (std::uint32_t k = 0; k < kRuns; ++k) {
      varA += (a[k][r] - meanA) * (a[k][r] - meanA) / (kRuns - 1);
      varB += (b[k][r] - meanB) * (b[k][r] - meanB) / (kRuns - 1);
    }
    const double difference = std::max(0.0, std::abs(meanA - meanB) - kTableAllowance * meanB);
    const double error = std::sqrt(varA / kRuns + varB / kRuns) + 1e-9;
    worstT = std::max(worstT, difference / error);
    worstRelative = std::max(worstRelative, std::abs(meanA - meanB) / std::max(meanB, 1e-6));
  }
  std::printf("%s: worst region |t| %.2f beyond the %.2f%% table allowance; worst relative difference %.4f\n", name,
              worstT, 100.0 * kTableAllowance, worstRelative);
  return worstT;
}

TEST_F(MeasuredRenderTest, PathTracedMeasuredMaterialMatchesTheModelItTabulates) {
  EXPECT_LT(worstRegionT(device(), gpu::kIntegratorPath, "path", 0), 5.0);
}

TEST_F(MeasuredRenderTest, SlidesMeasuredMaterialMatchesTheModelItTabulates) {
  EXPECT_LT(worstRegionT(device(), gpu::kIntegratorSlides, "slides", 0), 5.0);
}

// The test can fail: the other test file (a gold GGX metal) is not Cook-Torrance.
TEST_F(MeasuredRenderTest, AnotherMaterialsFileIsToldApart) {
  EXPECT_GT(worstRegionT(device(), gpu::kIntegratorSlides, "slides, another file", 1), 50.0);
}

}  // namespace
}  // namespace raylab::test
