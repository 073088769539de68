// The path integrator's two schedules on the ray-query backend, the megakernel and the wavefront
// (engine/render/wavefront.h), give the same image bit for bit: each path is the same computation on the same
// random numbers, and each pixel adds its samples in the same order. Checked on the committed path-traced scenes
// (an area light with glass and a mirror; every model under an HDR environment), with several samples per
// dispatch, and on an image large enough to be split into several waves.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "render/renderer.h"
#include "render/gpu_scene.h"
#include "builtin_scenes/load_scene.h"
#include "shared/features.h"
#include "support/gpu_test.h"
#include "util/error.h"

namespace raylab::test {
namespace {

class WavefrontTest : public GpuTest {};

struct Rendered {
  Image image;
  RayCounts rays;
  bool wavefront = false;
};

Rendered render(const Device& device, const Scene& scene, std::uint32_t width, std::uint32_t height,
                std::uint32_t spp, Schedule schedule) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.seed = 3;
  KernelFeatures kernel = featuresOf(scene);
  kernel.integrator = gpu::kIntegratorPath;
  settings.kernel = kernel;
  settings.schedule = schedule;
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, spp);
  Rendered result{readImage(device, renderer), renderer.rays, renderer.wavefrontActive};
  EXPECT_EQ(renderer.droppedSamples, 0u);
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  return result;
}

// `lanes`: the device's subgroup size (8 with lavapipe's 256-bit vectors, 4 with the tests' 128-bit ones).
void expectSameBits(const Rendered& megakernel, const Rendered& wavefront, const std::string& what,
                    std::uint32_t lanes) {
  ASSERT_FALSE(megakernel.wavefront) << what;
  ASSERT_TRUE(wavefront.wavefront) << what;
  ASSERT_EQ(megakernel.image.rgba.size(), wavefront.image.rgba.size()) << what;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < megakernel.image.rgba.size(); ++i) {
    differing += std::memcmp(&megakernel.image.rgba[i], &wavefront.image.rgba[i], sizeof(float)) != 0;
  }
  EXPECT_EQ(differing, 0u) << what << ": channel values that differ between the megakernel and the wavefront";
  // The same paths: the same rays of each kind.
  EXPECT_EQ(megakernel.rays.primary, wavefront.rays.primary) << what;
  EXPECT_EQ(megakernel.rays.shadow, wavefront.rays.shadow) << what;
  EXPECT_EQ(megakernel.rays.secondary, wavefront.rays.secondary) << what;
  // Every lane of a wavefront's segment dispatch has a live path but those of the last group of a queue.
  EXPECT_GT(laneUtilisation(wavefront.rays, lanes), 0.99) << what;
  EXPECT_LT(laneUtilisation(megakernel.rays, lanes), laneUtilisation(wavefront.rays, lanes)) << what;
}

TEST_F(WavefrontTest, TheCommittedPathTracedScenesAreBitIdenticalToTheMegakernel) {
  for (const char* file : {"cornell_box_area.gltf", "showcase_hdri.gltf"}) {
    const Scene scene = loadScene({std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/" + file, ""});
    // 96 x 64 pixels: renderSamples puts all 6 samples of a pixel into one dispatch, and so into one wave.
    expectSameBits(render(device(), scene, 96, 64, 6, Schedule::kMegakernel),
                   render(device(), scene, 96, 64, 6, Schedule::kWavefront), file, device().subgroupSize);
  }
}

TEST_F(WavefrontTest, AnImageOfSeveralWavesIsBitIdenticalToTheMegakernel) {
  const Scene scene = loadScene({std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/cornell_box_area.gltf", ""});
  // 256 x 256 pixels with 8 samples in one dispatch are 2^19 paths: two waves of kWaveCapacity.
  static_assert(kWaveCapacity < 256 * 256 * 8);
  expectSameBits(render(device(), scene, 256, 256, 8, Schedule::kMegakernel),
                 render(device(), scene, 256, 256, 8, Schedule::kWavefront), "several waves", device().subgroupSize);
}

// Automatically only for path kernels on ray queries in closed scenes, where it measured faster.
TEST_F(WavefrontTest, TheAutomaticChoiceIsTheWavefrontForPathKernelsOnRayQueriesInClosedScenes) {
  KernelFeatures path;
  path.integrator = gpu::kIntegratorPath;
  KernelFeatures slides;
  slides.integrator = gpu::kIntegratorSlides;
  EXPECT_TRUE(usesWavefront(Schedule::kAutomatic, path, Backend::kQuery, false));
  EXPECT_FALSE(usesWavefront(Schedule::kAutomatic, path, Backend::kQuery, true));
  EXPECT_TRUE(usesWavefront(Schedule::kWavefront, path, Backend::kQuery, true));
  EXPECT_FALSE(usesWavefront(Schedule::kAutomatic, path, Backend::kPipeline, false));
  EXPECT_FALSE(usesWavefront(Schedule::kAutomatic, slides, Backend::kQuery, false));
  EXPECT_FALSE(usesWavefront(Schedule::kMegakernel, path, Backend::kQuery, false));
  EXPECT_THROW(usesWavefront(Schedule::kWavefront, slides, Backend::kQuery, false), Error);
  EXPECT_THROW(usesWavefront(Schedule::kWavefront, path, Backend::kPipeline, false), Error);

  const Scene cornell = loadScene({std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/cornell_box_area.gltf", ""});
  const Scene hdri = loadScene({std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/showcase_hdri.gltf", ""});
  EXPECT_FALSE(lightEscapes(cornell));
  EXPECT_TRUE(lightEscapes(hdri));
}

}  // namespace
}  // namespace raylab::test
