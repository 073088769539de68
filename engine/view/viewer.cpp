#include "view/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <filesystem>

#include "util/error.h"
#include "view/viewer_state.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

// What a submitted frame did, for its completion (viewer_frames.cpp, completeFrame).
void recordSubmission(Viewer& v, FrameSlot& slot, const FramePlan& plan, double now, bool shown) {
  slot.submitSeconds = now;
  slot.shown = shown;
  slot.pixelSamples = plan.pixelSamples;
  slot.traceExtent = v.scheduler.traceExtent;
  slot.preview = v.scheduler.preview;
  slot.spp = v.scheduler.sampleIndex;
  slot.measure = v.kernelState == KernelState::kReady && plan.pixelSamples > 0;
  if (plan.pixelSamples > 0) v.kernelState = KernelState::kReady;
}

void countSubmission(Viewer& v, double now) {
  if (v.lastSubmit >= 0.0) {
    const double ms = (now - v.lastSubmit) * 1000.0;
    v.frameMs = v.frameMs == 0.0 ? ms : 0.8 * v.frameMs + 0.2 * ms;
  }
  v.lastSubmit = now;
  ++v.frameIndex;
}

// Everything after the image was acquired: input, UI, changes, the plan, recording and submission.
void drawFrame(Viewer& v, FrameSlot& slot, std::uint32_t imageIndex) {
  const double now = v.clock.seconds();
  const WindowInput input = takeInput(v.window);
  v.uiFramesLeft = input.activity ? kUiSettleFrames : v.uiFramesLeft - 1;

  beginUiFrame();
  PanelEdits edits;
  if (v.panelShown) {
    updateStatus(v);
    edits = drawPanel(v.scene, v.settings, v.selection, v.status, v.controller.sceneSize,
                      float(v.swapchain.extent.height), [&v] { drawComparisonSections(v); });
  }
  const bool cameraBlocked = handlePointer(v);  // dragging the divider, not the camera
  drawOverlay(v);
  if (updateCamera(v.controller, v.camera, pollCameraInput(v.window, input, v.cameraCursor),
                   !uiWantsMouse() && !cameraBlocked, !uiWantsKeyboard(), now - v.lastCameraUpdate)) {
    v.pending.accumulation = true;
  }
  v.lastCameraUpdate = now;
  handleHotKeys(v, input);
  if (edits.resetView) {
    v.camera = v.controller.home;
    v.pending.accumulation = true;
  }
  if (edits.maxDepth || edits.environment) v.pending.accumulation = true;
  if (edits.integrator) switchIntegrator(v);
  if (edits.denoise) setDenoise(v, v.settings.denoise);
  if (edits.resolutionScale) v.pending.extent = true;
  uploadSceneEdits(v, edits.materials, edits.lights);
  if (edits.screenshot) {
    const std::string path = timestampedScreenshotPath();
    saveScreenshot(v, path, screenshotPaths(path, "").png);
  }
  v.scheduler.settings.targetFrameSeconds = v.settings.targetMs / 1000.0;

  // Automation is deterministic: a frame with a change draws the preview, every other frame (the first
  // included) adds exactly one full-resolution pass, so that N still frames hold N samples per pixel.
  const bool fullPass = v.automation && (v.frameIndex == 0 || !v.pending.accumulation);
  const FrameKind kind = fullPass ? FrameKind::kFullPass : FrameKind::kInteractive;
  FramePlan plan;
  const bool paused = !covers(v.renderer.kernel, v.needed);  // waiting for a kernel with the scene's models
  if (!paused) {
    plan = planFrame(v.scheduler, now, v.pending.accumulation, kind);
    v.pending.accumulation = false;
    if (plan.reset) discardDenoised(v, true);  // before this frame's display pass reads it
    setTraceExtent(v.renderer, plan.traceExtent);
    setMaxDepth(v.renderer, v.settings.maxDepth);
    setSceneLighting(v.renderer, v.scene);
    setCamera(v.renderer, v.camera);
    if (v.comparison.active) {
      setTraceExtent(v.comparison.renderer, plan.traceExtent);
      setMaxDepth(v.comparison.renderer, v.settings.maxDepth);
      setSceneLighting(v.comparison.renderer, v.scene);
      setCamera(v.comparison.renderer, v.camera);
    }
  }

  const bool capture = !v.options.windowCapture.empty() && v.options.frames && v.frameIndex + 1 == *v.options.frames;
  recordFrame(v, slot, paused ? nullptr : &plan, imageIndex, capture, !paused && differenceStatsDue(v));
  recordSubmission(v, slot, plan, now, true);
  submitAndPresent(v, slot, imageIndex);
  v.lastShown = now;
  countSubmission(v, now);
}

// A refinement frame between displayed ones (kRefineDisplaySeconds): trace passes for the whole frame budget.
void drawUnshownFrame(Viewer& v, FrameSlot& slot, double now) {
  const FramePlan plan = planFrame(v.scheduler, now, false, FrameKind::kUnshown);
  recordUnshownFrame(v, slot, plan);
  recordSubmission(v, slot, plan, now, false);
  submitUnshown(v, slot);
  countSubmission(v, now);
}

void run(Viewer& v) {
  v.automation = v.options.frames.has_value();
  for (const ScriptEvent& event : v.options.script) v.lastScriptFrame = std::max(v.lastScriptFrame, event.frame);
  v.clock.restart();
  while (!windowShouldClose(v.window)) {
    if (v.automation && v.frameIndex >= *v.options.frames) break;
    reapFinishedFrames(v);
    if (v.options.exitWhenConverged && v.frameIndex > v.lastScriptFrame && converged(v.scheduler) && !anyInFlight(v) &&
        denoisedToTheLimit(v)) {
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
    updateDenoise(v);

    const VkExtent2D window = framebufferExtent(v.window);
    if (window.width == 0 || window.height == 0) {
      glfwWaitEvents();  // minimised: nothing to draw into, and no reason to spin
      continue;
    }
    if (v.pending.swapchain || window.width != v.swapchain.extent.width || window.height != v.swapchain.extent.height) {
      recreateSwapchain(v);
    }
    if (v.pending.extent) updateFullExtent(v);

    // Nothing to trace (refined to the limit, or waiting for a kernel) and no input: sleep until an event, but
    // wake up now and then while a kernel builds, to take it as soon as it is ready.
    const bool paused = !covers(v.renderer.kernel, v.needed);
    const bool traceWork = !paused && (v.pending.accumulation || !converged(v.scheduler));
    // A script's events are counted in frames: with --exit-at-limit and an event still ahead, the frames go on
    // (with nothing to trace they only display), or an image that converged first would wait for that frame forever.
    const bool scriptAhead = v.options.exitWhenConverged && v.frameIndex <= v.lastScriptFrame;
    if (!v.automation && !traceWork && !scriptAhead && !v.window.input->activity && v.uiFramesLeft <= 0 &&
        !v.pending.display) {
      if (anyInFlight(v)) continue;  // the fence wait above paces the loop
      glfwWaitEventsTimeout(v.build || v.denoised.job.valid() ? kBuildPollSeconds : kIdleWaitSeconds);
      continue;
    }

    // Refining with nothing to react to: most frames only trace, a few show the progress.
    const double now = v.clock.seconds();
    if (!v.automation && traceWork && !v.window.input->activity && v.uiFramesLeft <= 0 && !v.pending.accumulation &&
        !v.pending.display && refiningQuietly(v.scheduler, now) && now - v.lastShown < kRefineDisplaySeconds) {
      drawUnshownFrame(v, slot, now);
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
      v.pending.swapchain = true;
      continue;
    }
    if (acquired == VK_SUBOPTIMAL_KHR) v.pending.swapchain = true;  // use the image, recreate afterwards
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
    std::string line = statusLine(v.status);
    std::replace(line.begin(), line.end(), '\n', ' ');  // the panel's two lines, on one
    std::printf("raylab view: %u frames, %s\n", v.frameIndex, line.c_str());
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
