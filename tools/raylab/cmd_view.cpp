// `raylab view`: the interactive window (engine/view), plus the automation flags tests and docs use.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "command_line/cli.h"
#include "commands.h"
#include "session/gpu_session.h"
#include "builtin_scenes/load_scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "view_logic/script.h"
#include "view/slice_plot.h"
#include "view/viewer.h"
#include "render/render_choices.h"

namespace raylab {

namespace {

bool hasExtension(const std::string& path, const std::string& extension) {
  return std::filesystem::path(path).extension() == extension;
}

// What `raylab view` was given, before it becomes ViewerOptions.
struct ViewCommandOptions {
  ViewerOptions viewer;
  SceneRequest request;
  std::string scriptPath;
  std::string targetPath;
  std::string compare;
  std::string toneMap = "clamp";
  std::string integrator{kIntegratorOption.defaultValue};
  std::string backend{kBackendOption.defaultValue};
  float targetMs = 50.0f;
  bool noAntialiasing = false;
  bool noPanel = false;
  std::optional<std::uint32_t> frames;
  bool exitAtLimit = false;
};

void view(ViewCommandOptions command) {
  ViewerOptions& o = command.viewer;
  const std::optional<std::uint32_t>& frames = command.frames;
  o.backend = parseBackendChoice(command.backend, "raylab view: --backend");

  if (!o.screenshot.empty() && !hasExtension(o.screenshot, ".exr") && !hasExtension(o.screenshot, ".png")) {
    throw Error("raylab view: --screenshot: '" + o.screenshot + "' must end in .exr or .png", kExitUsage);
  }
  if (!o.screenshotPng.empty()) requireExtension("raylab view", "--png", o.screenshotPng, ".png");
  if (!o.screenshotPng.empty() && !hasExtension(o.screenshot, ".exr")) {
    throw Error("raylab view: --png names the PNG of --screenshot FILE.exr, which is missing", kExitUsage);
  }
  if (!o.windowCapture.empty()) requireExtension("raylab view", "--capture-window", o.windowCapture, ".png");
  if (!o.windowCapture.empty() && !frames) {
    throw Error("raylab view: --capture-window needs --frames (it captures the last frame)", kExitUsage);
  }
  if (frames && *frames == 0) throw Error("raylab view: --frames must be at least 1", kExitUsage);
  if (command.exitAtLimit && (frames || o.sppLimit == 0)) {
    throw Error("raylab view: --exit-at-limit needs a --spp-limit above 0 and no --frames", kExitUsage);
  }
  o.frames = frames;
  o.exitWhenConverged = command.exitAtLimit;
  o.targetMs = command.targetMs;
  o.toneMap = parseToneMap(command.toneMap);
  o.render.jitter = !command.noAntialiasing;
  o.integrator = parseIntegratorChoice(command.integrator, "raylab view: --integrator");
  o.panel = !command.noPanel;
  if (!command.scriptPath.empty()) o.script = loadScript(command.scriptPath);
  // With --frames N the viewer exits after frame N - 1: a later event would never happen.
  for (const ScriptEvent& event : o.script) {
    if (frames && event.frame >= *frames) {
      throw Error("raylab view: " + event.where + ": the event at frame " + std::to_string(event.frame) +
                      " would never run: --frames " + std::to_string(*frames) + " ends after frame " +
                      std::to_string(*frames - 1),
                  kExitUsage);
    }
  }
  // Every output is checked before the window opens, so that no session's work is lost to an unwritable path.
  if (!o.screenshot.empty()) {
    const ScreenshotPaths paths = screenshotPaths(o.screenshot, o.screenshotPng);
    checkOutputPath(paths.exr, "--screenshot");
    checkOutputPath(paths.png, "--screenshot");
  }
  if (!o.windowCapture.empty()) checkOutputPath(o.windowCapture, "--capture-window");
  if (!o.screenshot.empty() && !o.windowCapture.empty()) {
    // The screenshot's PNG would overwrite the capture (or the reverse), silently.
    const ScreenshotPaths paths = screenshotPaths(o.screenshot, o.screenshotPng);
    if (std::filesystem::weakly_canonical(paths.png) == std::filesystem::weakly_canonical(o.windowCapture)) {
      throw Error("raylab view: --capture-window " + o.windowCapture + " is also the PNG of --screenshot " +
                      o.screenshot + ": give one of them another name (or --png)",
                  kExitUsage);
    }
  }
  for (const ScriptEvent& event : o.script) {
    if (event.action == ScriptAction::kSaveLobe) checkOutputPath(event.name, event.where);
    if (event.action != ScriptAction::kScreenshot) continue;
    const ScreenshotPaths paths = screenshotPaths(event.name, "");
    checkOutputPath(paths.exr, event.where);
    checkOutputPath(paths.png, event.where);
  }

  // Read (and a bad one refused) before the scene loads and the window opens.
  if (!command.targetPath.empty()) o.target = loadSlicePlot(command.targetPath);

  SceneRequest request = command.request;
  request.maxBufferBytes = deviceBufferLimit(o.device);  // an environment image the device cannot hold is not decoded
  const Scene scene = loadScene(request);
  if (!command.compare.empty()) o.compare = parseCompareSpec(command.compare, scene, "raylab view: --compare");
  runViewer(scene, o);
}

}  // namespace

void addViewCommand(CLI::App& raylab) {
  auto o = std::make_shared<ViewCommandOptions>();
  CLI::App* command = addCommand(
      raylab, "view",
      "open an interactive window on a scene (X11; headless: xvfb-run -a)\n"
      "Opens a window on SCENE (glTF 2.0) or, without SCENE, the built-in default scene, and renders it with the "
      "same kernel as `raylab render`, progressively: while the view changes it traces a reduced resolution sized "
      "to hold --target-ms per frame, and when still it refines every pixel at full resolution. Needs an X11 "
      "display; headless, run it under `xvfb-run -a`.\n"
      "Controls (docs/viewer.md): left drag orbit, shift+left or middle drag pan, wheel zoom, right drag look + "
      "WASD/QE fly, R/Home reset view, F1/Tab panel, F12/P screenshot, Esc quit.",
      [o] {
        view(*o);
        return kExitOk;
      });
  addSceneOptions(command, o->request);
  addImageSizeOptions(command, o->viewer.width, o->viewer.height, "image", 8);
  addSampleOptions(command, o->viewer.render);
  addIntegratorOption(command, o->integrator);
  addFlag(command, "--no-aa", o->noAntialiasing, "sample pixel centres only (no anti-aliasing jitter)");
  addNumber(command, "--target-ms", o->targetMs, "frame time to hold while the view changes", 5.0f, 1000.0f);
  addCount(command, "--spp-limit", o->viewer.sppLimit, "stop refining at this many samples per pixel; 0: never", 0,
           kMaxSamplesPerPixel);
  addToneOptions(command, o->viewer.exposure, o->toneMap, "the display");
  addFlag(command, "--no-panel", o->noPanel, "start with the panel hidden (F1 shows it)");
  addFlag(command, "--denoise", o->viewer.denoise,
          "show the still image denoised by Open Image Denoise (the N key and the panel switch it; comparisons stay "
          "raw); exits 2 when the library (PyPI's pyoidn) is missing");
  addFlag(command, "--exit-at-limit", o->exitAtLimit,
          "exit once the still image has --spp-limit samples per pixel (after the script's last event), saving "
          "--screenshot: the interactive schedule, budgeted frames and all, for scripts and tests");
  addOptionalCount(command, "--frames", o->frames,
                   "run N frames and exit; each frame without a change adds one full pass", 0, UINT32_MAX);
  addText(command, "--compare", o->compare, "MATERIAL=MODEL[:k=v,...]",
          "open the split view: the right side renders MATERIAL as MODEL with these parameters (RGB as r/g/b), "
          "e.g. --compare \"red plastic=ward:alpha_x=0.2,alpha_y=0.2\"");
  addText(command, "--target", o->targetPath, "FILE.slice|FILE.binary",
          "a measured material beside the lobe: its phi_d = 90 slice, row by row, with the selected material's f at "
          "the same pairs (docs/fitting.md)");
  addText(command, "--script", o->scriptPath, "FILE", "replay camera and parameter changes (format in docs/viewer.md)");
  addText(command, "--screenshot", o->viewer.screenshot, "FILE.exr|FILE.png",
          "save the last frame's image: the EXR and the PNG, the one not named beside the other");
  addText(command, "--png", o->viewer.screenshotPng, "FILE.png", "where --screenshot FILE.exr writes its PNG");
  addText(command, "--capture-window", o->viewer.windowCapture, "FILE.png",
          "save the last frame's window, panel included (with --frames)");
  addBackendOption(command, o->backend);
  addDeviceOption(command, o->viewer.device);
}

}  // namespace raylab
