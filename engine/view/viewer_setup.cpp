// The viewer's set-up and tear-down: window, device, scene upload, renderer, display, UI; and the size changes
// that rebuild part of it (swapchain, traced extent).
#include "view/viewer_state.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "denoise/denoise.h"
#include "shared/features.h"
#include "util/error.h"
#include "vk/commands.h"
#include "vk/vk_check.h"

namespace raylab {

// The traced size for a window: its size times the resolution scale, shrunk (aspect kept) where the device
// cannot hold that many pixels in one accumulation buffer; the display pass scales the image up.
glm::uvec2 fullExtentFor(VkExtent2D window, float scale, std::uint64_t maxPixels) {
  double s = scale;
  const double pixels = double(window.width) * window.height * s * s;
  if (pixels > double(maxPixels)) s *= std::sqrt(double(maxPixels) / pixels) * 0.999;
  const auto scaled = [s](std::uint32_t size) {
    return std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::floor(size * s)), 8u, kMaxImageSide);
  };
  return {scaled(window.width), scaled(window.height)};
}

void openWindowAndDevice(Viewer& v) {
  std::string displayError;
  if (!initWindowSystem(displayError)) {
    // Check the device first, so that a machine without one exits 3 whether or not it has a display.
    Instance probe = createInstance({});
    try {
      const std::vector<DeviceReport> reports = surveyDevices(probe);
      chooseDevice(reports, v.options.device);
    } catch (...) {
      destroyInstance(probe);
      throw;
    }
    destroyInstance(probe);
    throw Error("raylab view needs an X11 display (" + displayError +
                "); on a machine without one, run it under Xvfb: xvfb-run -a raylab view ...");
  }
  v.windowSystem = true;
  InstanceOptions instanceOptions;
  instanceOptions.extensions = windowInstanceExtensions();
  v.instance = createInstance(instanceOptions);
  // --width and --height are the image's size; the panel's strip is added beside it.
  v.window = createWindow(v.instance.handle, v.options.width + (v.options.panel ? kPanelWidth : 0u), v.options.height,
                          "raylab view: " + v.scene.name);
  const std::vector<DeviceReport> reports = surveyDevices(v.instance, v.window.surface);
  const DeviceReport& chosen = reports[chooseDevice(reports, v.options.device)];
  if (!v.options.quiet) {
    std::fprintf(stderr, "raylab: device %u: %s (%s)\n", chosen.index, chosen.name.c_str(), chosen.driver.c_str());
  }
  v.device = createDevice(v.instance, chosen, v.window.surface);
  v.report.device = chosen.name;
  v.report.driver = chosen.driver;
}

// What the scene needs compiled in, with the integrator of the panel (chosen at start-up by --integrator).
KernelFeatures neededKernel(const Viewer& v) {
  KernelFeatures needed = featuresOf(v.scene);
  needed.integrator = v.integrator;
  if (v.settings.denoise) needed.features |= gpu::kFeatureAovs;  // the denoiser's albedo and normal
  return needed;
}

// Where the image goes in the window: right of the panel's strip while the panel shows, else everywhere.
VkRect2D imageArea(const Viewer& v) {
  const VkExtent2D window = v.swapchain.extent;
  const std::uint32_t left = v.panelShown ? std::min(kPanelWidth, window.width > 8 ? window.width - 8 : 0u) : 0u;
  return {{std::int32_t(left), 0}, {window.width - left, window.height}};
}

void setUp(Viewer& v) {
  if (v.options.denoise) {
    loadDenoiser();  // without it --denoise exits 2 before a window opens, saying how to install it
    v.settings.denoise = true;
  }
  openWindowAndDevice(v);
  while (framebufferExtent(v.window).width == 0 || framebufferExtent(v.window).height == 0) glfwWaitEvents();

  v.gpuScene = uploadScene(v.device, v.scene, {.materialsEditable = true});
  v.swapchain = createSwapchain(v.device, v.window.surface, framebufferExtent(v.window));
  if (!v.options.windowCapture.empty() && !(v.swapchain.usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT)) {
    throw Error("--capture-window: this window system does not let raylab read the window's images back");
  }
  const glm::uvec2 full = fullExtentFor(imageArea(v).extent, v.settings.resolutionScale, maxImagePixels(v.device));
  RenderSettings renderSettings = v.options.render;
  renderSettings.width = full.x;
  renderSettings.height = full.y;
  v.needed = neededKernel(v);
  renderSettings.kernel = v.needed;
  renderSettings.backend = chooseBackend(v.device, v.options.backend);
  v.renderer = createRenderer(v.device, v.gpuScene, v.scene, renderSettings);
  // The driver compiles the kernel at its first dispatch: seconds on a CPU device, with the window still blank.
  if (!v.options.quiet) {
    std::printf("raylab view: compiling the render kernel (%s); the first frame waits for it\n",
                describe(v.renderer.kernel).c_str());
    std::fflush(stdout);
  }
  v.status.device = std::string(renderSettings.backend == Backend::kPipeline ? "ray-tracing pipeline" : "ray queries") +
                    " on " + v.device.report.name;

  v.display = createDisplay(v.device, v.swapchain.format, full);
  bindAccumulation(v.device, v.display, v.renderer.accumulation.handle);
  bindCompared(v.device, v.display, v.renderer.accumulation.handle);  // until something is compared
  submitAndWait(v.device, [&](VkCommandBuffer cmd) { recordClearDisplay(cmd, v.display); });
  v.ui = createUi(v.instance, v.device, v.window, v.swapchain);
  for (FrameSlot& slot : v.slots) slot = createFrameSlot(v.device);

  v.scheduler.settings.targetFrameSeconds = v.options.targetMs / 1000.0;
  v.scheduler.settings.sppLimit = v.options.sppLimit;
  setFullExtent(v.scheduler, full);
  v.controller = makeCameraController(v.scene);
  v.camera = v.scene.camera;
  v.settings.maxDepth = v.options.render.maxDepth;
  v.settings.integrator = v.integrator;
  v.settings.exposure = v.options.exposure;
  v.settings.toneMap = v.options.toneMap;
  v.settings.targetMs = static_cast<float>(v.options.targetMs);
  v.report.fullExtent = full;
  if (v.options.compare) startComparing(v, *v.options.compare);
  v.slicePlot = v.options.target;
}

void tearDown(Viewer& v) {
  if (v.device.handle != VK_NULL_HANDLE) vkDeviceWaitIdle(v.device.handle);
  if (v.build) abandonKernelBuild(v.device, *v.build);
  for (FrameSlot& slot : v.slots) {
    if (v.device.handle != VK_NULL_HANDLE) destroyFrameSlot(v.device, slot);
  }
  if (v.device.handle != VK_NULL_HANDLE) {
    destroyLobePlot(v.device, v.lobe);
    stopComparison(v.device, v.comparison);
    destroyDenoisedView(v);
    destroyUi(v.device, v.ui);
    destroyDisplay(v.device, v.display);
    destroySwapchain(v.device, v.swapchain);
    destroyRenderer(v.device, v.renderer);
    destroyGpuScene(v.device, v.gpuScene);
    destroyDevice(v.device);
  }
  if (v.instance.handle != VK_NULL_HANDLE) {
    destroyWindow(v.instance.handle, v.window);
    destroyInstance(v.instance);
  }
  if (v.windowSystem) terminateWindowSystem();
}

void updateFullExtent(Viewer& v) {
  const glm::uvec2 full = fullExtentFor(imageArea(v).extent, v.settings.resolutionScale, maxImagePixels(v.device));
  v.pending.extent = false;
  if (full == v.scheduler.fullExtent) return;
  waitForFrames(v);
  discardDenoised(v, false);  // rebound below
  resizeRenderer(v.device, v.renderer, full.x, full.y);
  if (v.comparison.active) resizeRenderer(v.device, v.comparison.renderer, full.x, full.y);
  resizeDisplay(v.device, v.display, full);
  bindAccumulation(v.device, v.display, v.renderer.accumulation.handle);
  bindCompared(v.device, v.display,
               (v.comparison.active ? v.comparison.renderer : v.renderer).accumulation.handle);
  v.difference = {};
  submitAndWait(v.device, [&](VkCommandBuffer cmd) { recordClearDisplay(cmd, v.display); });
  setFullExtent(v.scheduler, full);
  v.report.fullExtent = full;
  v.pending.accumulation = true;
  v.pending.display = true;
  v.showingPreview = false;
}

void recreateSwapchain(Viewer& v) {
  waitForFrames(v);
  VK_CHECK(vkDeviceWaitIdle(v.device.handle));
  Swapchain next = createSwapchain(v.device, v.window.surface, framebufferExtent(v.window), v.swapchain.handle);
  destroySwapchain(v.device, v.swapchain);
  v.swapchain = std::move(next);
  recreateUiFramebuffers(v.device, v.ui, v.swapchain);
  v.pending.swapchain = false;
  updateFullExtent(v);
}

}  // namespace raylab
