// `raylab view`: the interactive window (engine/view), plus the automation flags tests and docs use.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "args.h"
#include "commands.h"
#include "gpu_session.h"
#include "scene/load_scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "view_logic/script.h"
#include "view/viewer.h"

namespace raylab {

namespace {

bool hasExtension(const std::string& path, const std::string& extension) {
  return std::filesystem::path(path).extension() == extension;
}

void requireExtension(const std::string& option, const std::string& path, const std::string& extension) {
  if (std::filesystem::path(path).extension() != extension) {
    throw Error("raylab view: " + option + ": '" + path + "' must end in " + extension, kExitUsage);
  }
}

ToneMap parseToneMap(const std::string& name) {
  if (name == "aces") return ToneMap::kAces;
  if (name == "reinhard") return ToneMap::kReinhard;
  return ToneMap::kClamp;
}

}  // namespace

int runView(int argc, char** argv) {
  ViewerOptions o;
  std::string scenePath;
  std::string camera;
  std::string scriptPath;
  std::string toneMap = "clamp";
  std::string integrator = "auto";
  std::string backend = "auto";
  std::string environment;
  std::optional<float> environmentStrength;
  std::optional<float> environmentRotation;
  float targetMs = 50.0f;
  bool noAntialiasing = false;
  bool allowOutsideUris = false;
  bool noPanel = false;
  std::optional<std::uint32_t> frames;
  ArgParser args("raylab view", "[SCENE] [options]",
                 "Opens a window on SCENE (glTF 2.0) or, without SCENE, the built-in default scene, and renders\n"
                 "it with the same kernel as `raylab render`, progressively: while the view changes it traces a\n"
                 "reduced resolution sized to hold --target-ms per frame, and when still it refines every pixel\n"
                 "at full resolution. Needs an X11 display; headless, run it under `xvfb-run -a`.\n"
                 "Controls (docs/viewer.md): left drag orbit, shift+left or middle drag pan, wheel zoom, right\n"
                 "drag look + WASD/QE fly, R/Home reset view, F1/Tab panel, F12/P screenshot, Esc quit.");
  args.positional("SCENE", &scenePath, "a .gltf or .glb file (default: the built-in scene)");
  args.option("--camera", &camera, "NAME", "the scene's camera to start from (default: its first)");
  args.flag("--allow-outside-uris", &allowOutsideUris,
            "let the scene's buffers and images lie outside its directory (only for files you trust)");
  args.option("--width", &o.width, "window width in pixels", 8, 16384);
  args.option("--height", &o.height, "window height in pixels", 8, 16384);
  args.option("--seed", &o.render.seed, "random seed of the sample pattern", 0, UINT32_MAX);
  args.option("--max-depth", &o.render.maxDepth, "bounces after the primary hit (mirror, glass)", 0, 64);
  args.choice("--integrator", &integrator, {"auto", "slides", "path"},
              "as raylab render: slides, path, or auto (default: path when the scene has an emissive surface or "
              "an environment image)");
  args.option("--env", &environment, "FILE.exr", "as raylab render: light the scene with this HDR image (+Y up)");
  args.option("--env-strength", &environmentStrength, "multiplies the environment image", 0.0f, 1e30f);
  args.option("--env-rotation", &environmentRotation, "turns the environment image about +Y, degrees", -360.0f, 360.0f);
  args.flag("--no-aa", &noAntialiasing, "sample pixel centres only (no anti-aliasing jitter)");
  args.option("--target-ms", &targetMs, "frame time to hold while the view changes", 5.0f, 1000.0f);
  args.option("--spp-limit", &o.sppLimit, "stop refining at this many samples per pixel; 0: never", 0, 1u << 20);
  args.option("--exposure", &o.exposure, "display exposure in stops", -20.0f, 20.0f);
  args.choice("--tonemap", &toneMap, {"clamp", "reinhard", "aces"}, "display tone curve (default clamp)");
  args.flag("--no-panel", &noPanel, "start with the panel hidden (F1 shows it)");
  args.option("--frames", &frames, "run N frames and exit; each frame without a change adds one full pass");
  args.option("--script", &scriptPath, "FILE", "replay camera and parameter changes (format in docs/viewer.md)");
  args.option("--screenshot", &o.screenshot, "FILE.exr|FILE.png",
              "save the last frame's image: the EXR and the PNG, the one not named beside the other");
  args.option("--png", &o.screenshotPng, "FILE.png", "where --screenshot FILE.exr writes its PNG");
  args.option("--capture-window", &o.windowCapture, "FILE.png",
              "save the last frame's window, panel included (with --frames)");
  addBackendOption(args, &backend);
  args.option("--device", &o.device, "Vulkan device index from `raylab devices` (default: best capable)");
  if (!args.parse(argc, argv)) return kExitOk;
  o.backend = parseBackendChoice(backend);

  if (!o.screenshot.empty() && !hasExtension(o.screenshot, ".exr") && !hasExtension(o.screenshot, ".png")) {
    throw Error("raylab view: --screenshot: '" + o.screenshot + "' must end in .exr or .png", kExitUsage);
  }
  if (!o.screenshotPng.empty()) requireExtension("--png", o.screenshotPng, ".png");
  if (!o.screenshotPng.empty() && !hasExtension(o.screenshot, ".exr")) {
    throw Error("raylab view: --png names the PNG of --screenshot FILE.exr, which is missing", kExitUsage);
  }
  if (!o.windowCapture.empty()) requireExtension("--capture-window", o.windowCapture, ".png");
  if (!o.windowCapture.empty() && !frames) {
    throw Error("raylab view: --capture-window needs --frames (it captures the last frame)", kExitUsage);
  }
  if (frames && *frames == 0) throw Error("raylab view: --frames must be at least 1", kExitUsage);
  o.frames = frames;
  o.targetMs = targetMs;
  o.toneMap = parseToneMap(toneMap);
  o.render.jitter = !noAntialiasing;
  o.integrator = integrator == "path" ? IntegratorChoice::kPath
                 : integrator == "slides" ? IntegratorChoice::kSlides
                                          : IntegratorChoice::kAuto;
  o.panel = !noPanel;
  if (!scriptPath.empty()) o.script = loadScript(scriptPath);
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
  for (const ScriptEvent& event : o.script) {
    if (event.action != ScriptAction::kScreenshot) continue;
    const ScreenshotPaths paths = screenshotPaths(event.name, "");
    checkOutputPath(paths.exr, event.where);
    checkOutputPath(paths.png, event.where);
  }

  const Scene scene = loadScene({scenePath, camera, allowOutsideUris, environment, environmentStrength,
                                 environmentRotation});
  runViewer(scene, o);
  return kExitOk;
}

}  // namespace raylab
