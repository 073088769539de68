// Changes to what the viewer shows: screenshots, scene edits from the panel and the script, hot keys, and the
// status line.
#include "view/viewer_state.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <ctime>

#include "render/render_choices.h"
#include "shared/features.h"
#include "util/error.h"
#include "view_logic/scene_edits.h"

namespace raylab {

std::string timestampedScreenshotPath() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "out/view-%Y%m%d-%H%M%S.exr", std::localtime(&now));
  return name;
}

void saveScreenshot(Viewer& v, const std::string& exrPath, const std::string& pngPath) {
  waitForFrames(v);
  if (v.denoised.showing) {
    // What is shown: the denoised image, and the files say so.
    writeExr(exrPath, v.denoised.image);
    writePng(pngPath, v.denoised.image, v.settings.exposure, v.settings.toneMap);
    v.status.message = "saved " + exrPath + " (denoised at " + std::to_string(v.denoised.shownSamples) + " spp)";
    if (!v.options.quiet) {
      std::printf("wrote %s (denoised at %u spp)\nwrote %s (denoised at %u spp)\n", exrPath.c_str(),
                  v.denoised.shownSamples, pngPath.c_str(), v.denoised.shownSamples);
    }
    return;
  }
  const Image image = readImage(v.device, v.renderer);
  writeExr(exrPath, image);
  if (v.comparison.active) {
    // The PNG as displayed: the split or the difference view, as display.comp draws it (the EXR is side A; the
    // comparison's own files follow).
    checkFinite(image, pngPath);
    const Image compared = readImage(v.device, v.comparison.renderer);
    const Rgb8Image shown = displayedImage(image, &compared, displaySettings(v));
    writePngRgb8(pngPath, shown.width, shown.height, shown.rgb.data());
  } else {
    writePng(pngPath, image, v.settings.exposure, v.settings.toneMap);
  }
  v.status.message = "saved " + exrPath + " (" + std::to_string(v.scheduler.sampleIndex) + " spp)";
  if (!v.options.quiet) std::printf("wrote %s\nwrote %s\n", exrPath.c_str(), pngPath.c_str());
  saveComparison(v, exrPath);
}

void uploadSceneEdits(Viewer& v, bool materials, bool lights) {
  if (!materials && !lights) return;
  waitForFrames(v);  // on a CPU device the buffers are host memory that running frames read
  if (materials) {
    const MaterialUpdate update = updateMaterials(v.device, v.gpuScene, v.scene.materials);
    if (update.tablesReplaced) writeSceneDescriptors(v.device, v.renderer.trace.descriptors.set, v.gpuScene);
    // Emission turned on where the scene had none: the surface shows its emission, but no light record samples it.
    if (!update.emittersComplete) {
      v.status.message = "a material without light records now emits: lights it adds are seen but not sampled "
                         "(next event estimation) until the scene is loaded again";
    }
  }
  if (lights) updateLights(v.device, v.gpuScene, v.scene.lights);
  v.needed = neededKernel(v);
  ensureKernel(v);
  if (materials) refreshComparison(v);
  v.pending.accumulation = true;
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
      case ScriptAction::kDenoise:
        setDenoise(v, event.param == "on");
        break;
      case ScriptAction::kSetMaxDepth:
        v.settings.maxDepth = static_cast<std::uint32_t>(event.value.x);
        break;
      case ScriptAction::kSetIntegrator:
        v.settings.integrator = chooseIntegrator(v.scene, parseIntegratorChoice(event.param, event.where));
        switchIntegrator(v);
        break;
      case ScriptAction::kSetEnvironmentStrength:
      case ScriptAction::kSetEnvironmentRotation:
        applyToScene(event, v.scene);
        break;
      case ScriptAction::kResize: {
        // Checked before the window grows: a window the device cannot render would still allocate its
        // swapchain and display images (gigabytes at 16384 x 16384) before the renderer refused it.
        const std::uint64_t pixels = std::uint64_t(event.value.x) * std::uint64_t(event.value.y);
        if (pixels > maxImagePixels(v.device)) {
          throw Error(event.where + ": resize to " + std::to_string(std::uint32_t(event.value.x)) + "x" +
                      std::to_string(std::uint32_t(event.value.y)) + " is more than the device renders (" +
                      std::to_string(maxImagePixels(v.device)) + " pixels, its maxStorageBufferRange)");
        }
        // The size of the image, as --width/--height: the panel's strip comes on top.
        if (!requestWindowSize(v.window, std::uint32_t(event.value.x) + (v.panelShown ? kPanelWidth : 0u),
                               std::uint32_t(event.value.y), kResizeTimeout)) {
          throw Error(event.where + ": the window system did not resize the window within " +
                      std::to_string(int(kResizeTimeout)) + " s");
        }
        break;
      }
      case ScriptAction::kScreenshot: {
        const ScreenshotPaths paths = screenshotPaths(event.name, "");
        saveScreenshot(v, paths.exr, paths.png);
        break;
      }
      case ScriptAction::kCompare:
      case ScriptAction::kSetDivider:
      case ScriptAction::kSetDifference:
      case ScriptAction::kPick:
      case ScriptAction::kSaveLobe:
        applyCompareEvent(v, event);
        break;
    }
    if (event.action == ScriptAction::kOrbit || event.action == ScriptAction::kPan ||
        event.action == ScriptAction::kZoom) {
      checkCameraEvent(v, event);
    }
    if (resetsAccumulation(event)) v.pending.accumulation = true;
  }
  uploadSceneEdits(v, materials, lights);
}

void handleHotKeys(Viewer& v, const WindowInput& input) {
  if (uiWantsKeyboard()) return;
  for (int key : input.keysPressed) {
    if (key == GLFW_KEY_ESCAPE) requestWindowClose(v.window);
    if (key == GLFW_KEY_F1 || key == GLFW_KEY_TAB) {
      v.panelShown = !v.panelShown;
      v.pending.extent = true;  // the image takes the panel's strip, or gives it back
    }
    if (key == GLFW_KEY_N) setDenoise(v, !v.settings.denoise);
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
  v.status.denoise = denoiseStatus(v);
}

}  // namespace raylab
