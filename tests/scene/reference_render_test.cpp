// Every committed scene against its reference, as Mitsuba 3's render tests do: a small image (40x24 pixels,
// the scene's camera and integrator) whose per-pixel mean and variance were measured from 32 independent renders
// of 32 spp each (tests/data/references/<scene>_mean.exr and _variance.exr), and a fresh image of 32 independent
// 8-spp renders with other seeds tested against them pixel by pixel. A change that alters an image (a formula, a
// sampler, the glass branch chosen at random beyond the queue, the throughput cut-off) shifts pixels by many
// standard errors and fails; noise alone passes.
//
// The statistics: Welch's t-test per pixel and channel, t = (x - m) / sqrt(s_x^2 / 32 + s_m^2 / 32), each mean with
// the variance of its own batches, so that a firefly in the fresh image inflates its own variance rather than
// failing the test (path tracing's samples are heavy-tailed, and with 16 batches a sky pixel under a sun was once
// seen at t = 7.6 while 48 batches showed no bias at all). Welch's degrees of freedom are at least 31, and the
// critical value is taken at 15 to allow for that skew. Each of the N =
// 2880 values is tested two-sided at alpha / N with alpha = 0.01 (Bonferroni): a scene raises a false alarm with
// probability at most 1%. Values without noise in either image (the sky, black) must match to float rounding. A
// second test compares each scene's mean over all pixels with its standard error (z-test, alpha = 0.001), which
// sees a bias of a few tenths of a percent spread over the image that no single pixel shows. Seeds are fixed, so a
// run either passes or fails, every time.
//
// RAYLAB_UPDATE_REFERENCES=1 renders the references instead (after a change that alters images on purpose), then
// the test runs against them; commit the files with the change. RAYLAB_UPDATE_REFERENCES=missing renders only those
// of scenes that have none yet.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "gltf_test_support.h"
#include <glm/gtc/matrix_transform.hpp>

#include "brdf_params/material_params.h"
#include "image/image.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "scene/shapes.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kWidth = 40;
constexpr std::uint32_t kHeight = 24;
constexpr std::uint32_t kReferenceSpp = 32;
constexpr std::uint32_t kReferenceBatches = 32;
constexpr std::uint32_t kFirstReferenceSeed = 1000;
constexpr std::uint32_t kFreshSpp = 8;
constexpr std::uint32_t kFreshBatches = 32;
constexpr std::uint32_t kFirstFreshSeed = 100;
// Two-sided critical value of Student's t with 15 degrees of freedom at alpha / 2880 = 3.47e-6 (alpha = 0.01),
// 1.74e-6 in each tail (by numerical integration of the t density): conservative for the 31 and more of Welch.
constexpr double kPixelCriticalT = 7.13;
constexpr double kImageCriticalZ = 3.29;  // two-sided, alpha = 0.001

class ReferenceRenderTest : public GpuTest {};

// No committed scene splits a path at glass more often than the slides' integrator queues (4 continuations),
// so the random choice of one branch beyond the queue would go untested. This scene does: three glass spheres
// one behind the other in the camera's view, in front of a lit backdrop, at max depth 16.
constexpr const char* kGlassRowName = "glass_row";

Scene glassRowScene() {
  Scene scene;
  scene.name = kGlassRowName;
  scene.materials.push_back({"backdrop", lambertMaterial(glm::vec3(0.8f, 0.5f, 0.3f))});
  for (float eta : {1.5f, 2.2f, 1.5f}) {
    gpu::MaterialRecord glass = defaultRecord(modelId("glass"));
    setParam(glass, "eta", glm::vec3(eta), "test");
    scene.materials.push_back({"glass", glass});
  }
  glm::mat4 wall = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  wall[3] = glm::vec4(0.0f, 0.0f, -6.0f, 1.0f);
  scene.meshes.push_back(makeGroundPlane(10.0f, 0.0f));
  scene.instances.push_back({0, wall, 0});
  scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.2f, 0.0f)), 0});
  scene.spheres.push_back({{0.0f, 0.0f, 1.5f}, 1.0f, 1});
  scene.spheres.push_back({{0.3f, 0.1f, -0.5f}, 0.9f, 2});
  scene.spheres.push_back({{-0.2f, -0.1f, -2.5f}, 1.0f, 3});
  scene.lights.push_back({"light", pointLight({2.0f, 3.0f, 3.0f}, glm::vec3(40.0f))});
  scene.lights.push_back({"back light", pointLight({-1.0f, 1.0f, -4.0f}, glm::vec3(10.0f))});
  scene.camera.position = {0.0f, 0.2f, 6.0f};
  scene.camera.target = {0.0f, 0.0f, -2.0f};
  return scene;
}

fs::path referencePath(const std::string& scene, const char* kind) {
  return fs::path(RAYLAB_SOURCE_DIR) / "tests" / "data" / "references" / (scene + "_" + kind + ".exr");
}

RenderSettings referenceSettings(const Scene& scene, std::uint32_t seed) {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.seed = seed;
  settings.maxDepth = kGlassRowName == scene.name ? 16 : 8;
  KernelFeatures kernel = featuresOf(scene);
  kernel.integrator = chooseIntegrator(scene, IntegratorChoice::kAuto);
  settings.kernel = kernel;
  return settings;
}

struct BatchStatistics {
  Image mean;      // over the batches
  Image variance;  // of one batch, unbiased
};

// The mean and the variance over `batches` renders of `spp` samples with seeds firstSeed, firstSeed + 1, ...:
// one renderer, reset between batches (the backends' agreement on these scenes is scene_render_test's).
BatchStatistics renderBatches(const Device& device, const Scene& scene, std::uint32_t batches, std::uint32_t spp,
                              std::uint32_t firstSeed) {
  BatchStatistics result{Image(kWidth, kHeight), Image(kWidth, kHeight)};
  std::vector<double> sum(result.mean.rgba.size(), 0.0), squares(result.mean.rgba.size(), 0.0);
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, referenceSettings(scene, firstSeed));
  for (std::uint32_t b = 0; b < batches; ++b) {
    renderer.params.seed = firstSeed + b;
    resetAccumulation(device, renderer);
    renderSamples(device, renderer, spp);
    const Image batch = readImage(device, renderer);
    for (std::size_t i = 0; i < sum.size(); ++i) {
      sum[i] += batch.rgba[i];
      squares[i] += double(batch.rgba[i]) * batch.rgba[i];
    }
  }
  EXPECT_EQ(renderer.droppedSamples, 0u) << scene.name << ": NaN or Inf samples were dropped";
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double m = sum[i] / batches;
    result.mean.rgba[i] = float(m);
    result.variance.rgba[i] = float(std::max(0.0, (squares[i] - batches * m * m) / (batches - 1)));
  }
  return result;
}

// Renders the reference of `scene` with RAYLAB_UPDATE_REFERENCES set, then tests a fresh image against it.
void expectMatchesReference(const Device& device, const Scene& scene, const std::string& name) {
  SCOPED_TRACE(name);
  {
    // RAYLAB_UPDATE_REFERENCES=missing writes the references of new scenes only, leaving every committed one as
    // it is; any other value rewrites them all.
    const char* update = std::getenv("RAYLAB_UPDATE_REFERENCES");
    const bool missing = !fs::exists(referencePath(name, "mean"));
    if (update != nullptr && (std::string(update) != "missing" || missing)) {
      const BatchStatistics reference =
          renderBatches(device, scene, kReferenceBatches, kReferenceSpp, kFirstReferenceSeed);
      writeExr(referencePath(name, "mean").string(), reference.mean);
      writeExr(referencePath(name, "variance").string(), reference.variance);
    }
    ASSERT_TRUE(fs::exists(referencePath(name, "mean")))
        << "no reference for " << name << ": run this test with RAYLAB_UPDATE_REFERENCES=missing and commit "
        << referencePath(name, "mean").parent_path();
    const Image mean = readExr(referencePath(name, "mean").string());
    const Image variance = readExr(referencePath(name, "variance").string());
    ASSERT_EQ(mean.width, kWidth);
    ASSERT_EQ(mean.height, kHeight);
    const BatchStatistics fresh = renderBatches(device, scene, kFreshBatches, kFreshSpp, kFirstFreshSeed);

    std::size_t rejected = 0, exactMismatches = 0;
    double worstT = 0.0;
    std::size_t worst = 0;
    double freshSum = 0.0, referenceSum = 0.0, varianceSum = 0.0;
    for (std::size_t i = 0; i < mean.rgba.size(); ++i) {
      if (i % 4 == 3) continue;  // alpha
      const double difference = double(fresh.mean.rgba[i]) - mean.rgba[i];
      // The variance of each mean: a batch's variance over the number of batches.
      const double meansVariance =
          double(fresh.variance.rgba[i]) / kFreshBatches + double(variance.rgba[i]) / kReferenceBatches;
      freshSum += fresh.mean.rgba[i];
      referenceSum += mean.rgba[i];
      varianceSum += meansVariance;
      if (meansVariance == 0.0) {
        // No noise in either image: the value is deterministic (sky, black), up to float rounding of the means.
        if (std::abs(difference) > 1e-5 * (1.0 + std::abs(mean.rgba[i]))) ++exactMismatches;
        continue;
      }
      const double t = difference / std::sqrt(meansVariance);
      if (std::abs(t) > kPixelCriticalT) ++rejected;
      if (std::abs(t) > worstT) {
        worstT = std::abs(t);
        worst = i;
      }
    }
    EXPECT_EQ(rejected, 0u) << name << ": pixels outside the reference's noise; the worst, value " << worst
                            << " (pixel " << worst / 4 % kWidth << ", " << worst / 4 / kWidth << "), has |t| = "
                            << worstT << " > " << kPixelCriticalT << ": fresh " << fresh.mean.rgba[worst]
                            << ", reference " << mean.rgba[worst] << " +- " << std::sqrt(variance.rgba[worst]);
    EXPECT_EQ(exactMismatches, 0u) << name << ": noiseless pixels that changed";
    const std::size_t values = std::size_t(kWidth) * kHeight * 3;
    const double z = (freshSum - referenceSum) / std::sqrt(std::max(varianceSum, 1e-30));
    EXPECT_LT(std::abs(z), kImageCriticalZ)
        << name << ": the image's mean moved: " << freshSum / values << " against " << referenceSum / values
        << " (z = " << z << ")";
  }
}

TEST_F(ReferenceRenderTest, EveryCommittedSceneMatchesItsReferencePixelByPixel) {
  const std::vector<fs::path> files = assetFiles();
  ASSERT_FALSE(files.empty()) << "no scenes in " << assetsDirectory();
  for (const fs::path& file : files) {
    WarningCapture warnings;
    expectMatchesReference(device(), loadGltfFile(file.string(), {}), file.stem().string());
  }
}

TEST_F(ReferenceRenderTest, GlassBeyondTheQueueMatchesItsReference) {
  expectMatchesReference(device(), glassRowScene(), kGlassRowName);
}

}  // namespace
}  // namespace raylab::test
