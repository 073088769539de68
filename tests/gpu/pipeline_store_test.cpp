// The device's pipeline store (vk/pipeline_store.h): a kernel built before on the device is handed out again
// instead of built again (a renderer made twice, a Python Renderer per call), a kernel of
// other constants is built anew, renders through a shared pipeline are the same, and everything the store keeps
// is destroyed with the device (the suite's validation check at teardown would report a leak).
#include <gtest/gtest.h>

#include "builtin_scenes/default_scene.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "support/gpu_test.h"
#include "vk/pipeline.h"
#include "vk/pipeline_store.h"

namespace raylab::test {
namespace {

class PipelineStoreTest : public GpuTest {};

RenderSettings settingsFor(const Scene& scene, IntegratorChoice integrator) {
  RenderSettings settings;
  settings.width = 16;
  settings.height = 8;
  KernelOptions options;
  options.integrator = integrator;
  settings.kernel = kernelFor(scene, options);
  return settings;
}

TEST_F(PipelineStoreTest, ARendererOfAKernelBuiltBeforeGetsTheSamePipeline) {
  const Scene scene = makeDefaultScene();
  GpuScene gpuScene = uploadScene(device(), scene);
  const std::size_t storedBefore = storeOf(device()).storedPipelines();
  Renderer first = createRenderer(device(), gpuScene, scene, settingsFor(scene, IntegratorChoice::kSlides));
  Renderer second = createRenderer(device(), gpuScene, scene, settingsFor(scene, IntegratorChoice::kSlides));
  Renderer path = createRenderer(device(), gpuScene, scene, settingsFor(scene, IntegratorChoice::kPath));
  EXPECT_NE(first.trace.pipeline, VK_NULL_HANDLE);
  EXPECT_EQ(first.trace.pipeline, second.trace.pipeline) << "the same kernel was built twice";
  EXPECT_NE(first.trace.pipeline, path.trace.pipeline) << "another integrator's kernel was not built";
  EXPECT_EQ(storeOf(device()).storedPipelines(), storedBefore + 2);

  // Both renderers of the shared pipeline render, and alike.
  renderSamples(device(), first, 2);
  renderSamples(device(), second, 2);
  EXPECT_TRUE(readImage(device(), first).rgba == readImage(device(), second).rgba);

  // Released, the pipelines stay stored: a renderer made again finds its kernel.
  const VkPipeline slides = first.trace.pipeline;
  destroyRenderer(device(), first);
  destroyRenderer(device(), second);
  EXPECT_EQ(storeOf(device()).storedPipelines(), storedBefore + 2);
  Renderer again = createRenderer(device(), gpuScene, scene, settingsFor(scene, IntegratorChoice::kSlides));
  EXPECT_EQ(again.trace.pipeline, slides);
  destroyRenderer(device(), again);
  destroyRenderer(device(), path);
  destroyGpuScene(device(), gpuScene);
}

}  // namespace
}  // namespace raylab::test
