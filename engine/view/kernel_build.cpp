#include "view/kernel_build.h"

#include <cstdlib>
#include <cstring>
#include <exception>

#include "render/gpu_scene.h"
#include "util/error.h"
#include "util/timer.h"
#include "vk/pipeline.h"

namespace raylab {

namespace {

bool shaderCacheDisabled() {
  const char* value = std::getenv("MESA_SHADER_CACHE_DISABLE");
  return value != nullptr && (std::strcmp(value, "true") == 0 || std::strcmp(value, "1") == 0 ||
                              std::strcmp(value, "yes") == 0);
}

// The smallest scene that makes every binding valid: the compiled code depends on the SPIR-V and the
// specialization constants, not on the data.
Scene warmUpScene() {
  Scene scene;
  scene.name = "kernel warm-up";
  scene.materials = {{"warm-up", lambertMaterial(glm::vec3(0.5f))}};
  scene.spheres = {{glm::vec3(0.0f), 1.0f, 0}};
  scene.lights = {{"warm-up", pointLight(glm::vec3(0.0f, 3.0f, 3.0f), glm::vec3(1.0f))}};
  return scene;
}

// One 8x8 dispatch of `kernel` on a device of our own, on the viewer's backend and schedule.
void warmUp(const Instance& instance, const DeviceReport& report, const KernelFeatures& kernel, Backend backend,
            Schedule schedule) {
  Device device = createDevice(instance, report);
  GpuScene gpuScene;
  Renderer renderer;
  try {
    const Scene scene = warmUpScene();
    gpuScene = uploadScene(device, scene);
    RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.kernel = kernel;
    settings.backend = backend;
    settings.schedule = schedule;
    renderer = createRenderer(device, gpuScene, scene, settings);
    renderSamples(device, renderer, 1);
  } catch (...) {
    destroyRenderer(device, renderer);
    destroyGpuScene(device, gpuScene);
    destroyDevice(device);
    throw;
  }
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  destroyDevice(device);
}

}  // namespace

std::unique_ptr<KernelBuild> startKernelBuild(const Instance& instance, const Device& device, const Renderer& renderer,
                                              const KernelFeatures& kernel) {
  auto build = std::make_unique<KernelBuild>();
  build->kernel = kernel;
  const bool warm = device.report.type == VK_PHYSICAL_DEVICE_TYPE_CPU && !shaderCacheDisabled();
  // The thread gets copies of the handles it reads: the main thread goes on changing the renderer's state.
  build->thread = std::thread([&device, instance, rendererHandles = renderer, kernel, warm, b = build.get()] {
    const Stopwatch clock;
    bool built = true;
    try {
      // A kernel this device built before is in the device's store, compiled by its first dispatch then: nothing
      // to build and nothing to warm up. Only this thread adds to the
      // store while a build runs (the main thread releases at the swap, after it), so the count tells.
      const std::size_t storedBefore = storeOf(device).storedPipelines();
      b->pipelines = createRenderPipelines(device, rendererHandles, kernel);
      built = storeOf(device).storedPipelines() != storedBefore;
    } catch (const std::exception& error) {
      b->error = error.what();
    }
    // The warm-up only saves time: if it fails, the first dispatch on the viewer's queue compiles instead.
    if (warm && built && b->error.empty()) {
      try {
        warmUp(instance, device.report, kernel, rendererHandles.trace.backend, rendererHandles.schedule);
        b->warmedUp = true;
      } catch (const std::exception&) {
        b->warmedUp = false;
      }
    }
    b->seconds = clock.seconds();
    b->finished.store(true);
  });
  return build;
}

RenderPipelines finishKernelBuild(const Device& device, KernelBuild& build) {
  if (build.thread.joinable()) build.thread.join();
  if (!build.error.empty()) {
    destroyRenderPipelines(device, build.pipelines);
    throw Error("building the kernel for " + describe(build.kernel) + " failed: " + build.error);
  }
  const RenderPipelines pipelines = build.pipelines;
  build.pipelines = {};
  return pipelines;
}

void abandonKernelBuild(const Device& device, KernelBuild& build) {
  if (build.thread.joinable()) build.thread.join();
  destroyRenderPipelines(device, build.pipelines);
}

}  // namespace raylab
