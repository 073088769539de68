#include "view/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <filesystem>
#include <memory>

#include "render/kernel_features.h"
#include "render/gpu_scene.h"
#include "shared/features.h"
#include "shared/frame.h"
#include "util/error.h"
#include "util/files.h"
#include "util/timer.h"
#include "view/camera_input.h"
#include "view_logic/camera_controller.h"
#include "view/display.h"
#include "view/frame_slot.h"
#include "view/kernel_build.h"
#include "view/panel.h"
#include "view_logic/scheduler.h"
#include "view/swapchain.h"
#include "view/ui.h"
#include "view/window.h"
#include "vk/commands.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

constexpr std::uint32_t kFramesInFlight = 2;
constexpr std::uint64_t kPollNanoseconds = 2'000'000;  // a fence wait never keeps input waiting longer
constexpr int kUiSettleFrames = 3;     // frames drawn after an input event while idle (ImGui hover states)
constexpr double kResizeTimeout = 5.0;  // seconds a scripted resize may take
constexpr double kRaysWindow = 1.0;     // rays/s over this many seconds of frames
constexpr double kIdleWaitSeconds = 0.5;    // idle: the status line still refreshes this often
constexpr double kBuildPollSeconds = 0.05;  // a kernel build's end is noticed within this

bool covers(const KernelFeatures& kernel, const KernelFeatures& needed) {
  return (needed.models & ~kernel.models) == 0 && (needed.features & ~kernel.features) == 0 &&
         needed.integrator == kernel.integrator;
}

std::string timestampedScreenshotPath() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "out/view-%Y%m%d-%H%M%S.exr", std::localtime(&now));
  return name;
}

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

struct Viewer {
  Viewer(const Scene& s, const ViewerOptions& o) : options(o), scene(s), panelShown(o.panel) {}

  const ViewerOptions& options;
  Scene scene;  // edited live by the panel and the script
  bool panelShown = true;  // the panel's strip beside the image (F1 toggles it)
  std::uint32_t integrator = chooseIntegrator(scene, options.integrator);
  bool windowSystem = false;
  Instance instance;
  Window window;
  Device device;
  GpuScene gpuScene;
  Renderer renderer;
  Swapchain swapchain;
  Display display;
  Ui ui;
  std::array<FrameSlot, kFramesInFlight> slots;

  Scheduler scheduler;
  CameraController controller;
  CursorTracker cursor;
  Camera camera;
  ViewSettings settings;
  PanelStatus status;
  PanelSelection selection;
  std::unique_ptr<KernelBuild> build;
  KernelFeatures needed;      // what the scene's materials and lights need compiled in
  bool freshKernel = true;    // the pipeline's next dispatch is its first: the driver compiles, do not time it
  bool changed = true;        // the accumulation is stale: the next plan resets it
  bool swapchainStale = false;
  bool extentStale = false;   // the resolution scale changed, or the panel was shown or hidden
  bool displayStale = true;   // the display images were cleared: the next display pass covers everything
  DisplaySettings lastDisplay;
  bool showingPreview = false;  // the window shows the preview image (else the refined one)
  glm::uvec2 previewSize{0};
  bool automation = false;
  std::uint32_t frameIndex = 0;       // frames submitted
  std::int64_t eventsAppliedFor = -1;  // the frame whose script events were applied
  std::uint32_t lastScriptFrame = 0;
  int uiFramesLeft = kUiSettleFrames;
  Stopwatch clock;
  double lastSubmit = -1.0;
  double lastCameraUpdate = 0.0;
  double frameMs = 0.0;
  std::deque<std::pair<double, std::uint64_t>> recentRays;  // (completion time, rays of that frame)
  ViewerReport report;
};

// ---- set-up and tear-down ----

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
  return needed;
}

// Where the image goes in the window: right of the panel's strip while the panel shows, else everywhere.
VkRect2D imageArea(const Viewer& v) {
  const VkExtent2D window = v.swapchain.extent;
  const std::uint32_t left = v.panelShown ? std::min(kPanelWidth, window.width > 8 ? window.width - 8 : 0u) : 0u;
  return {{std::int32_t(left), 0}, {window.width - left, window.height}};
}

void setUp(Viewer& v) {
  openWindowAndDevice(v);
  while (framebufferExtent(v.window).width == 0 || framebufferExtent(v.window).height == 0) glfwWaitEvents();

  v.gpuScene = uploadScene(v.device, v.scene);
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
  v.status.device = std::string(renderSettings.backend == Backend::kPipeline ? "ray-tracing pipeline" : "ray queries") +
                    " on " + v.device.report.name;

  v.display = createDisplay(v.device, v.swapchain.format, full);
  bindAccumulation(v.device, v.display, v.renderer.accumulation.handle);
  submitAndWait(v.device, [&](VkCommandBuffer cmd) { recordClearDisplay(cmd, v.display); });
  v.ui = createUi(v.instance, v.device, v.window, v.swapchain);
  v.ui.visible = v.panelShown;
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
}

void tearDown(Viewer& v) {
  if (v.device.handle != VK_NULL_HANDLE) vkDeviceWaitIdle(v.device.handle);
  if (v.build) abandonKernelBuild(v.device, *v.build);
  for (FrameSlot& slot : v.slots) {
    if (v.device.handle != VK_NULL_HANDLE) destroyFrameSlot(v.device, slot);
  }
  if (v.device.handle != VK_NULL_HANDLE) {
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

// ---- completed frames ----

void writeWindowCapture(const Viewer& v, const FrameSlot& slot) {
  const std::string& path = v.options.windowCapture;
  const VkExtent2D extent = slot.captureExtent;
  const bool bgra = v.swapchain.format == VK_FORMAT_B8G8R8A8_UNORM || v.swapchain.format == VK_FORMAT_B8G8R8A8_SRGB;
  const auto* pixels = static_cast<const std::uint8_t*>(slot.capture.mapped);
  std::vector<std::uint8_t> rgb(std::size_t(extent.width) * extent.height * 3);
  for (std::size_t i = 0; i < std::size_t(extent.width) * extent.height; ++i) {
    rgb[i * 3 + 0] = pixels[i * 4 + (bgra ? 2 : 0)];
    rgb[i * 3 + 1] = pixels[i * 4 + 1];
    rgb[i * 3 + 2] = pixels[i * 4 + (bgra ? 0 : 2)];
  }
  writePngRgb8(path, extent.width, extent.height, rgb.data());
  if (!v.options.quiet) std::printf("wrote %s\n", path.c_str());
}

void completeFrame(Viewer& v, FrameSlot& slot) {
  const double now = v.clock.seconds();
  const FrameTimes times = readFrameTimes(v.device, slot);
  if (slot.measure) addTraceMeasurement(v.scheduler.cost, slot.pixelSamples, times.traceSeconds);
  // The first frames also compile the display and UI pipelines.
  if (v.report.frames.size() >= kFramesInFlight) {
    addOverheadMeasurement(v.scheduler.cost, times.totalSeconds - times.traceSeconds);
  }
  const auto* stats = static_cast<const gpu::RayStats*>(slot.rayStats.mapped);
  const std::uint64_t rays = std::uint64_t(stats->primaryRays) + stats->shadowRays + stats->secondaryRays;
  v.recentRays.emplace_back(now, rays);
  while (!v.recentRays.empty() && v.recentRays.front().first < now - kRaysWindow) v.recentRays.pop_front();

  FrameRecord record;
  record.submitSeconds = slot.submitSeconds;
  record.completeSeconds = now;
  record.traceSeconds = times.traceSeconds;
  record.deviceSeconds = times.totalSeconds;
  record.displaySeconds = times.displaySeconds;
  record.blitSeconds = times.blitSeconds;
  record.traceExtent = slot.traceExtent;
  record.preview = slot.preview;
  record.spp = slot.spp;
  record.pixelSamples = slot.pixelSamples;
  v.report.frames.push_back(record);
  if (slot.captured) writeWindowCapture(v, slot);
  slot.inFlight = false;
  slot.captured = false;
}

void reapFinishedFrames(Viewer& v) {
  for (FrameSlot& slot : v.slots) {
    if (slot.inFlight && vkGetFenceStatus(v.device.handle, slot.fence) == VK_SUCCESS) completeFrame(v, slot);
  }
}

// Blocks until no frame is in flight: before the host writes what frames read (materials, lights) or frees
// what they use (buffers, pipelines, the swapchain).
void waitForFrames(Viewer& v) {
  for (FrameSlot& slot : v.slots) {
    if (!slot.inFlight) continue;
    VK_CHECK(vkWaitForFences(v.device.handle, 1, &slot.fence, VK_TRUE, UINT64_MAX));
    completeFrame(v, slot);
  }
}

bool anyInFlight(const Viewer& v) {
  return std::any_of(v.slots.begin(), v.slots.end(), [](const FrameSlot& slot) { return slot.inFlight; });
}

// ---- changes ----

void saveScreenshot(Viewer& v, const std::string& exrPath, const std::string& pngPath) {
  waitForFrames(v);
  const Image image = readImage(v.device, v.renderer);
  writeExr(exrPath, image);
  writePng(pngPath, image, v.settings.exposure, v.settings.toneMap);
  v.status.message = "saved " + exrPath + " (" + std::to_string(v.scheduler.sampleIndex) + " spp)";
  if (!v.options.quiet) std::printf("wrote %s\nwrote %s\n", exrPath.c_str(), pngPath.c_str());
}

void installKernel(Viewer& v) {
  RenderPipelines pipelines;
  try {
    pipelines = finishKernelBuild(v.device, *v.build);
  } catch (const Error& error) {
    v.build.reset();
    if (v.automation) throw;
    v.status.message = error.what();
    return;
  }
  waitForFrames(v);  // the old pipeline may still be running
  char message[160];
  std::snprintf(message, sizeof message, "kernel rebuilt in %.2f s%s: %s", v.build->seconds,
                v.build->warmedUp ? " (compiled off-queue)" : "", describe(v.build->kernel).c_str());
  swapRenderPipelines(v.device, v.renderer, pipelines, v.build->kernel);
  v.status.message = message;
  if (!v.options.quiet) std::printf("raylab view: %s\n", message);
  v.build.reset();
  v.freshKernel = true;
  v.changed = true;
}

// Starts a background build when the scene needs models or features the kernel lacks. Until it is swapped in
// the viewer traces nothing and keeps showing the last image.
void ensureKernel(Viewer& v) {
  if (covers(v.renderer.kernel, v.needed) || v.build) return;  // a running build is re-checked when it lands
  KernelFeatures wanted = v.needed;
  wanted.models |= v.renderer.kernel.models;
  wanted.features |= v.renderer.kernel.features;
  v.build = startKernelBuild(v.instance, v.device, v.renderer, wanted);
  if (v.automation) installKernel(v);  // automation is deterministic: the frame waits for its kernel
}

// The integrator of v.settings: a kernel of its own, built in the background like a new model's.
void switchIntegrator(Viewer& v) {
  if (v.integrator == v.settings.integrator) return;
  v.integrator = v.settings.integrator;
  v.needed = neededKernel(v);
  ensureKernel(v);
  v.changed = true;
}

void uploadSceneEdits(Viewer& v, bool materials, bool lights) {
  if (!materials && !lights) return;
  waitForFrames(v);  // on a CPU device the buffers are host memory that running frames read
  if (materials) updateMaterials(v.device, v.gpuScene, v.scene.materials);
  if (lights) updateLights(v.device, v.gpuScene, v.scene.lights);
  v.needed = neededKernel(v);
  ensureKernel(v);
  v.changed = true;
}

// A camera that a script moved out of float range, or onto its own target, is the script's error: say which line.
void checkCameraEvent(const Viewer& v, const ScriptEvent& event) {
  gpu::FrameParams probe{};
  try {
    applyCamera(probe, v.camera, v.renderer.params.width, v.renderer.params.height);
  } catch (const Error& error) {
    throw Error(event.where + ": this camera move leaves no usable view (" + error.what() + ")");
  }
  const glm::vec3 position = v.camera.position;
  if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
    throw Error(event.where + ": this camera move puts the camera outside float range");
  }
}

void applyScriptEvents(Viewer& v) {
  if (v.eventsAppliedFor == std::int64_t(v.frameIndex)) return;
  v.eventsAppliedFor = v.frameIndex;
  bool materials = false, lights = false;
  for (const ScriptEvent& event : v.options.script) {
    if (event.frame != v.frameIndex) continue;
    switch (event.action) {
      case ScriptAction::kOrbit:
        orbitCamera(v.camera, glm::radians(event.value.x), glm::radians(event.value.y));
        break;
      case ScriptAction::kPan:
        panCamera(v.camera, event.value.x, event.value.y);
        break;
      case ScriptAction::kZoom:
        zoomCamera(v.camera, event.value.x, 1.0e-4f * v.controller.sceneSize);
        break;
      case ScriptAction::kSetMaterial:
      case ScriptAction::kModel:
      case ScriptAction::kSetLightIntensity:
      case ScriptAction::kSetLightPosition:
      case ScriptAction::kSetLightDirection:
      case ScriptAction::kSetLightCone: {
        const SceneEffect effect = applyToScene(event, v.scene);
        materials |= effect.materials;
        lights |= effect.lights;
        break;
      }
      case ScriptAction::kSetExposure:
        v.settings.exposure = event.value.x;
        break;
      case ScriptAction::kSetMaxDepth:
        v.settings.maxDepth = static_cast<std::uint32_t>(event.value.x);
        break;
      case ScriptAction::kSetIntegrator:
        v.settings.integrator = event.param == "path" ? gpu::kIntegratorPath : gpu::kIntegratorSlides;
        switchIntegrator(v);
        break;
      case ScriptAction::kSetEnvironmentStrength:
      case ScriptAction::kSetEnvironmentRotation:
        if (!v.scene.environment.hasImage()) {
          throw Error(event.where + ": the scene has no environment image (give one with --env FILE.exr)");
        }
        if (event.action == ScriptAction::kSetEnvironmentStrength) v.scene.environment.strength = event.value.x;
        else v.scene.environment.rotation = glm::radians(event.value.x);
        break;
      case ScriptAction::kResize:
        // The size of the image, as --width/--height: the panel's strip comes on top.
        if (!requestWindowSize(v.window, std::uint32_t(event.value.x) + (v.panelShown ? kPanelWidth : 0u),
                               std::uint32_t(event.value.y), kResizeTimeout)) {
          throw Error(event.where + ": the window system did not resize the window within " +
                      std::to_string(int(kResizeTimeout)) + " s");
        }
        break;
      case ScriptAction::kScreenshot: {
        const ScreenshotPaths paths = screenshotPaths(event.name, "");
        saveScreenshot(v, paths.exr, paths.png);
        break;
      }
    }
    if (event.action == ScriptAction::kOrbit || event.action == ScriptAction::kPan ||
        event.action == ScriptAction::kZoom) {
      checkCameraEvent(v, event);
    }
    if (resetsAccumulation(event)) v.changed = true;
  }
  uploadSceneEdits(v, materials, lights);
}

void updateFullExtent(Viewer& v) {
  const glm::uvec2 full = fullExtentFor(imageArea(v).extent, v.settings.resolutionScale, maxImagePixels(v.device));
  v.extentStale = false;
  if (full == v.scheduler.fullExtent) return;
  waitForFrames(v);
  resizeRenderer(v.device, v.renderer, full.x, full.y);
  resizeDisplay(v.device, v.display, full);
  bindAccumulation(v.device, v.display, v.renderer.accumulation.handle);
  submitAndWait(v.device, [&](VkCommandBuffer cmd) { recordClearDisplay(cmd, v.display); });
  setFullExtent(v.scheduler, full);
  v.report.fullExtent = full;
  v.changed = true;
  v.displayStale = true;
  v.showingPreview = false;
}

void recreateSwapchain(Viewer& v) {
  waitForFrames(v);
  VK_CHECK(vkDeviceWaitIdle(v.device.handle));
  Swapchain next = createSwapchain(v.device, v.window.surface, framebufferExtent(v.window), v.swapchain.handle);
  destroySwapchain(v.device, v.swapchain);
  v.swapchain = std::move(next);
  recreateUiFramebuffers(v.device, v.ui, v.swapchain);
  v.swapchainStale = false;
  updateFullExtent(v);
}

void handleHotKeys(Viewer& v, const WindowInput& input) {
  if (uiWantsKeyboard()) return;
  for (int key : input.keysPressed) {
    if (key == GLFW_KEY_ESCAPE) requestWindowClose(v.window);
    if (key == GLFW_KEY_F1 || key == GLFW_KEY_TAB) {
      v.panelShown = !v.panelShown;
      v.ui.visible = v.panelShown;
      v.extentStale = true;  // the image takes the panel's strip, or gives it back
    }
    if (key == GLFW_KEY_F12 || key == GLFW_KEY_P) {
      const std::string path = timestampedScreenshotPath();
      saveScreenshot(v, path, screenshotPaths(path, "").png);
    }
  }
}

void updateStatus(Viewer& v) {
  v.status.spp = v.scheduler.sampleIndex;
  v.status.traceExtent = v.scheduler.traceExtent;
  v.status.preview = v.scheduler.preview;
  v.status.frameMs = v.frameMs;
  std::uint64_t rays = 0;
  for (const auto& [time, count] : v.recentRays) rays += count;
  const double span = v.recentRays.size() > 1 ? v.recentRays.back().first - v.recentRays.front().first : 0.0;
  v.status.raysPerSecond = span > 0.0 ? double(rays - v.recentRays.front().second) / span : 0.0;
  v.status.compiling = v.build != nullptr;
}

// ---- one frame ----

void recordCapture(VkCommandBuffer cmd, Viewer& v, FrameSlot& slot, VkImage image) {
  const VkExtent2D extent = v.swapchain.extent;
  const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (slot.capture.size < bytes) {
    destroyBuffer(v.device, slot.capture);
    slot.capture = createBuffer(v.device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kHost, "window capture");
  }
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                       nullptr, 0, nullptr, 1, &barrier);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.capture.handle, 1, &region);
  computeBarrier(cmd);  // the copy's writes become visible to the host
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.dstAccessMask = 0;
  barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &barrier);
  slot.captured = true;
  slot.captureExtent = extent;
}

void recordFrame(Viewer& v, FrameSlot& slot, const FramePlan* plan, std::uint32_t imageIndex, bool capture) {
  VkCommandBuffer cmd = slot.cmd;
  VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
  vkCmdResetQueryPool(cmd, slot.timestamps, 0, kFrameTimestampCount);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, slot.timestamps, kFrameBegin);
  computeBarrier(cmd);  // after the previous frame's passes and the uploads

  if (plan != nullptr && plan->reset) {
    const VkDeviceSize bytes = VkDeviceSize(plan->traceExtent.x) * plan->traceExtent.y * sizeof(glm::vec4);
    vkCmdFillBuffer(cmd, v.renderer.accumulation.handle, 0, bytes, 0);
    computeBarrier(cmd);
  }
  recordResetRayStats(cmd, v.renderer);
  if (plan != nullptr) {
    for (const TracePass& pass : plan->passes) {
      recordSamplePass(cmd, v.renderer, pass.sampleIndex, pass.tile.origin, pass.tile.size);
    }
  }
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, slot.timestamps, kTraceEnd);
  recordCopyRayStats(cmd, v.renderer, slot.rayStats.handle);

  // The display pass: the whole preview while moving; while refining only the tiles traced this frame (the
  // refined image keeps its texels), which saves most of the pass at large sizes.
  const glm::uvec2 traced = v.scheduler.traceExtent;
  const DisplaySettings display{v.settings.exposure, v.settings.toneMap};
  const bool settingsChanged = !(display == v.lastDisplay) || v.displayStale;
  const bool traceDone = plan != nullptr && !plan->passes.empty();
  if (traced.x > 0 && traced.y > 0 && v.scheduler.preview) {
    if (traceDone || settingsChanged || !v.showingPreview) {
      const Tile whole{glm::uvec2(0), traced};
      recordDisplayRegions(cmd, v.display, v.display.preview, traced, display, {&whole, 1});
    }
    v.showingPreview = true;
    v.previewSize = traced;
  } else if (traced.x > 0 && traced.y > 0) {
    if (v.showingPreview) {
      // Refinement starts: the last preview, stretched, stands in for the pixels not traced yet.
      recordPreviewToRefined(cmd, v.display, v.previewSize);
      v.showingPreview = false;
    }
    std::vector<Tile> regions;
    if (settingsChanged) {
      regions = tilesWithSamples(v.scheduler);
    } else if (traceDone) {
      for (const TracePass& pass : plan->passes) {
        // A small image may take several passes in a frame: each tile once.
        const bool seen = std::any_of(regions.begin(), regions.end(),
                                      [&](const Tile& tile) { return tile.origin == pass.tile.origin; });
        if (!seen) regions.push_back(pass.tile);
      }
    }
    recordDisplayRegions(cmd, v.display, v.display.refined, traced, display, regions);
  }
  v.lastDisplay = display;
  v.displayStale = false;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, slot.timestamps, kDisplayEnd);
  const VkImage image = v.swapchain.images[imageIndex];
  if (v.showingPreview) {
    recordToSwapchain(cmd, v.display, v.display.preview, v.previewSize, image, imageArea(v));
  } else {
    recordToSwapchain(cmd, v.display, v.display.refined, v.display.extent, image, imageArea(v));
  }
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, slot.timestamps, kBlitEnd);
  recordUi(cmd, v.ui, v.swapchain, imageIndex);
  if (capture) recordCapture(cmd, v, slot, image);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps, kFrameEnd);
  VK_CHECK(vkEndCommandBuffer(cmd));
}

void submitAndPresent(Viewer& v, FrameSlot& slot, std::uint32_t imageIndex) {
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;  // the blit is the first use of the image
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &slot.imageAvailable;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &slot.cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &v.swapchain.renderFinished[imageIndex];
  VK_CHECK(vkResetFences(v.device.handle, 1, &slot.fence));
  VK_CHECK(vkQueueSubmit(v.device.queue, 1, &submit, slot.fence));
  slot.inFlight = true;

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &v.swapchain.renderFinished[imageIndex];
  present.swapchainCount = 1;
  present.pSwapchains = &v.swapchain.handle;
  present.pImageIndices = &imageIndex;
  const VkResult result = vkQueuePresentKHR(v.device.queue, &present);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) v.swapchainStale = true;
  else VK_CHECK(result);
}

// Everything after the image was acquired: input, UI, changes, the plan, recording and submission.
void drawFrame(Viewer& v, FrameSlot& slot, std::uint32_t imageIndex) {
  const double now = v.clock.seconds();
  const WindowInput input = takeInput(v.window);
  v.uiFramesLeft = input.activity ? kUiSettleFrames : v.uiFramesLeft - 1;

  beginUiFrame();
  PanelEdits edits;
  if (v.ui.visible) {
    updateStatus(v);
    edits = drawPanel(v.scene, v.settings, v.selection, v.status, v.controller.sceneSize,
                      float(v.swapchain.extent.height));
  }
  if (updateCamera(v.controller, v.camera, pollCameraInput(v.window, input, v.cursor), !uiWantsMouse(),
                   !uiWantsKeyboard(), now - v.lastCameraUpdate)) {
    v.changed = true;
  }
  v.lastCameraUpdate = now;
  handleHotKeys(v, input);
  if (edits.resetView) {
    v.camera = v.controller.home;
    v.changed = true;
  }
  if (edits.maxDepth || edits.environment) v.changed = true;
  if (edits.integrator) switchIntegrator(v);
  if (edits.resolutionScale) v.extentStale = true;
  uploadSceneEdits(v, edits.materials, edits.lights);
  if (edits.screenshot) {
    const std::string path = timestampedScreenshotPath();
    saveScreenshot(v, path, screenshotPaths(path, "").png);
  }
  v.scheduler.settings.targetFrameSeconds = v.settings.targetMs / 1000.0;

  // Automation is deterministic: a frame with a change draws the preview, every other frame (the first
  // included) adds exactly one full-resolution pass, so that N still frames hold N samples per pixel.
  const bool fullPass = v.automation && (v.frameIndex == 0 || !v.changed);
  const FrameKind kind = fullPass ? FrameKind::kFullPass : FrameKind::kInteractive;
  FramePlan plan;
  const bool paused = !covers(v.renderer.kernel, v.needed);  // waiting for a kernel with the scene's models
  if (!paused) {
    plan = planFrame(v.scheduler, now, v.changed, kind);
    v.changed = false;
    v.renderer.params.width = plan.traceExtent.x;
    v.renderer.params.height = plan.traceExtent.y;
    v.renderer.params.maxDepth = v.settings.maxDepth;
    v.renderer.params.environmentStrength = v.scene.environment.strength;
    v.renderer.params.environmentRotation = v.scene.environment.rotation;
    v.renderer.params.background = v.scene.background;
    setCamera(v.renderer, v.camera);
  }

  const bool capture = !v.options.windowCapture.empty() && v.options.frames && v.frameIndex + 1 == *v.options.frames;
  recordFrame(v, slot, paused ? nullptr : &plan, imageIndex, capture);
  slot.submitSeconds = now;
  slot.pixelSamples = plan.pixelSamples;
  slot.traceExtent = v.scheduler.traceExtent;
  slot.preview = v.scheduler.preview;
  slot.spp = v.scheduler.sampleIndex;
  slot.measure = !v.freshKernel && plan.pixelSamples > 0;
  if (plan.pixelSamples > 0) v.freshKernel = false;
  submitAndPresent(v, slot, imageIndex);

  if (v.lastSubmit >= 0.0) {
    const double ms = (now - v.lastSubmit) * 1000.0;
    v.frameMs = v.frameMs == 0.0 ? ms : 0.8 * v.frameMs + 0.2 * ms;
  }
  v.lastSubmit = now;
  ++v.frameIndex;
}

void run(Viewer& v) {
  v.automation = v.options.frames.has_value();
  for (const ScriptEvent& event : v.options.script) v.lastScriptFrame = std::max(v.lastScriptFrame, event.frame);
  v.clock.restart();
  while (!windowShouldClose(v.window)) {
    if (v.automation && v.frameIndex >= *v.options.frames) break;
    reapFinishedFrames(v);
    if (v.options.exitWhenConverged && v.frameIndex > v.lastScriptFrame && converged(v.scheduler) && !anyInFlight(v)) {
      break;
    }
    FrameSlot& slot = v.slots[v.frameIndex % kFramesInFlight];
    if (slot.inFlight) {
      // The device is still busy with this slot's frame: keep the window responsive and look again soon.
      const VkResult waited = vkWaitForFences(v.device.handle, 1, &slot.fence, VK_TRUE, kPollNanoseconds);
      if (waited != VK_TIMEOUT) VK_CHECK(waited);
      glfwPollEvents();
      continue;
    }
    glfwPollEvents();
    if (v.build && v.build->finished.load()) {
      installKernel(v);
      ensureKernel(v);  // the scene may have moved on while it was building
    }
    applyScriptEvents(v);

    const VkExtent2D window = framebufferExtent(v.window);
    if (window.width == 0 || window.height == 0) {
      glfwWaitEvents();  // minimised: nothing to draw into, and no reason to spin
      continue;
    }
    if (v.swapchainStale || window.width != v.swapchain.extent.width || window.height != v.swapchain.extent.height) {
      recreateSwapchain(v);
    }
    if (v.extentStale) updateFullExtent(v);

    // Nothing to trace (refined to the limit, or waiting for a kernel) and no input: sleep until an event, but
    // wake up now and then while a kernel builds, to take it as soon as it is ready.
    const bool paused = !covers(v.renderer.kernel, v.needed);
    const bool traceWork = !paused && (v.changed || !converged(v.scheduler));
    if (!v.automation && !traceWork && !v.window.input->activity && v.uiFramesLeft <= 0) {
      if (anyInFlight(v)) continue;  // the fence wait above paces the loop
      glfwWaitEventsTimeout(v.build ? kBuildPollSeconds : kIdleWaitSeconds);
      continue;
    }

    std::uint32_t imageIndex = 0;
    const VkResult acquired =
        vkAcquireNextImageKHR(v.device.handle, v.swapchain.handle, 0, slot.imageAvailable, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_NOT_READY || acquired == VK_TIMEOUT) {
      glfwWaitEventsTimeout(0.002);  // the presentation engine holds every image: poll input, try again
      continue;
    }
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
      v.swapchainStale = true;
      continue;
    }
    if (acquired == VK_SUBOPTIMAL_KHR) v.swapchainStale = true;  // use the image, recreate afterwards
    else VK_CHECK(acquired);
    drawFrame(v, slot, imageIndex);
  }
  waitForFrames(v);
  v.report.spp = v.scheduler.sampleIndex;
  if (!v.options.screenshot.empty()) {
    const ScreenshotPaths paths = screenshotPaths(v.options.screenshot, v.options.screenshotPng);
    saveScreenshot(v, paths.exr, paths.png);
  }
  if (!v.options.quiet) {
    updateStatus(v);
    std::printf("raylab view: %u frames, %s\n", v.frameIndex, statusLine(v.status).c_str());
  }
}

}  // namespace

ScreenshotPaths screenshotPaths(const std::string& named, const std::string& pngOverride) {
  std::filesystem::path path(named);
  if (path.extension() == ".png") return {std::filesystem::path(path).replace_extension(".exr").string(), named};
  return {named, pngOverride.empty() ? path.replace_extension(".png").string() : pngOverride};
}

ViewerReport runViewer(const Scene& scene, const ViewerOptions& options) {
  checkScript(options.script, scene);
  Viewer viewer(scene, options);
  try {
    setUp(viewer);
    run(viewer);
  } catch (...) {
    tearDown(viewer);
    throw;
  }
  tearDown(viewer);
  return std::move(viewer.report);
}

}  // namespace raylab
