// No leak on any failure (issue 22): every Vulkan object is owned so that a throw at any step of scene upload,
// renderer creation or rendering releases everything created before it. The test hook failAtCreation
// (vk/vk_check.h) makes the Nth creating call (vkCreate..., vkAllocate...) fail with
// VK_ERROR_OUT_OF_DEVICE_MEMORY; for N = 1, 2, ... until a run completes, each run uploads the default scene
// (meshes, spheres, textures, lights, the environment), creates a renderer and renders a sample on a fresh device,
// on both backends and both schedules. Each failure must be a clear error naming the call, and destroying the
// device afterwards must draw no validation message (the layers report every object still alive then).
#include <gtest/gtest.h>

#include <string>

#include "builtin_scenes/default_scene.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "util/error.h"
#include "vk/device.h"
#include "vk/vk_check.h"

namespace raylab::test {
namespace {

struct Variant {
  const char* name;
  Backend backend;
  Schedule schedule;
  IntegratorChoice integrator;
};

// One run: the device is the test's, the failure injected from the scene upload on. True when it completed.
bool runOnce(const Device& device, const Scene& scene, const Variant& variant, unsigned failAt, std::string& error) {
  RenderSettings settings;
  settings.width = 16;
  settings.height = 8;
  settings.backend = variant.backend;
  settings.schedule = variant.schedule;
  KernelOptions kernel;
  kernel.integrator = variant.integrator;
  settings.kernel = kernelFor(scene, kernel);
  failAtCreation(failAt);
  try {
    GpuScene gpuScene = uploadScene(device, scene);
    try {
      Renderer renderer = createRenderer(device, gpuScene, scene, settings);
      try {
        renderSamples(device, renderer, 1);
      } catch (...) {
        destroyRenderer(device, renderer);
        throw;
      }
      destroyRenderer(device, renderer);
    } catch (...) {
      destroyGpuScene(device, gpuScene);
      throw;
    }
    destroyGpuScene(device, gpuScene);
  } catch (const Error& e) {
    failAtCreation(0);
    error = e.what();
    return false;
  }
  failAtCreation(0);
  return true;
}

TEST(FailureInjection, EveryCreationStepFailsCleanlyWithoutLeaks) {
  InstanceOptions options;
  options.validation = true;
  Instance instance = createInstance(options);
  const std::vector<DeviceReport> reports = surveyDevices(instance);
  const DeviceReport& report = reports[chooseDevice(reports, std::nullopt)];
  Scene scene = makeDefaultScene();
  scene.lights.resize(std::min<std::size_t>(scene.lights.size(), 2));
  const Variant variants[] = {
      {"ray queries, megakernel, slides", Backend::kQuery, Schedule::kMegakernel, IntegratorChoice::kSlides},
      {"ray queries, wavefront, path", Backend::kQuery, Schedule::kWavefront, IntegratorChoice::kPath},
      {"ray-tracing pipeline, path", Backend::kPipeline, Schedule::kMegakernel, IntegratorChoice::kPath}};
  for (const Variant& variant : variants) {
    unsigned steps = 0;
    for (unsigned n = 1; n < 500; ++n) {
      Device device = createDevice(instance, report);
      const std::uint32_t before = validationMessageCount();
      std::string error;
      const bool completed = runOnce(device, scene, variant, n, error);
      destroyDevice(device);
      const bool clean = validationMessageCount() == before;
      EXPECT_TRUE(clean) << variant.name << ": objects left alive (or other validation messages) after failing "
                         << "creation step " << n << ": " << error;
      if (completed) break;
      ++steps;
      // A clear error: the failed call and VK_ERROR_OUT_OF_DEVICE_MEMORY, or the allocator's own message.
      const bool clear = error.find("VK_ERROR_OUT_OF_DEVICE_MEMORY") != std::string::npos ||
                         error.find("the Vulkan device is out of memory") != std::string::npos;
      EXPECT_TRUE(clear) << variant.name << " step " << n << ": " << error;
      if (!clean || !clear) break;  // one report per variant, not one per later step
    }
    std::printf("%s: %u creation steps failed in turn\n", variant.name, steps);
    EXPECT_GT(steps, 10u) << variant.name << ": the hook reached too few creation steps";
  }
  destroyInstance(instance);
}

}  // namespace
}  // namespace raylab::test
