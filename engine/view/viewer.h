// `raylab view`: the interactive window. One main thread polls input, builds the UI and records short
// submissions; it never waits for trace work (docs/viewer.md explains the scheduling).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "view_logic/compare_spec.h"
#include "view/slice_plot.h"
#include "view_logic/script.h"

namespace raylab {

struct ViewerOptions {
  std::uint32_t width = 960;  // window size in pixels
  std::uint32_t height = 540;
  RenderSettings render;      // seed, max depth, jitter; the size follows the window
  IntegratorChoice integrator = IntegratorChoice::kAuto;
  BackendChoice backend = BackendChoice::kAuto;
  std::optional<std::uint32_t> device;
  double targetMs = 50.0;
  std::uint32_t sppLimit = 1024;  // 0: refine forever
  float exposure = 0.0f;
  ToneMap toneMap = ToneMap::kClamp;
  bool panel = true;
  bool denoise = false;  // show the still image denoised (Open Image Denoise), as the N key and the panel switch
  std::optional<CompareSpec> compare;  // open the split view with this material switched (--compare)
  std::optional<SlicePlot> target;     // a measured slice shown beside the lobe (--target), read and checked


  // Automation. With `frames`, the viewer runs that many frames and exits, deterministically: a frame with a
  // change (a script event) draws the preview, every other frame, the first included, adds exactly one
  // full-resolution pass, so N frames without changes hold what `raylab render --spp N` computes.
  std::optional<std::uint32_t> frames;
  std::vector<ScriptEvent> script;
  std::string screenshot;     // FILE.exr or FILE.png of the last frame's accumulation; the other beside it
  std::string screenshotPng;  // overrides the PNG's path of a FILE.exr screenshot
  std::string windowCapture;  // PNG of the last frame's window, panel included
  bool exitWhenConverged = false;  // exit once still at full resolution with sppLimit samples (benchmarks)
  bool quiet = false;
};

// One frame, as the benchmark sees it.
struct FrameRecord {
  double submitSeconds = 0.0;    // since the viewer started its loop
  double completeSeconds = 0.0;  // when the main thread saw its fence
  double traceSeconds = 0.0;     // device time of its trace passes
  double displaySeconds = 0.0;   // device time of the display pass
  double blitSeconds = 0.0;      // device time of the blit to the window
  double deviceSeconds = 0.0;    // device time of the whole frame (the UI pass is what the others leave)
  glm::uvec2 traceExtent{0};
  bool preview = false;
  bool shown = true;             // displayed; else a refinement frame that only traced (kRefineDisplaySeconds)
  std::uint32_t spp = 0;         // complete passes at traceExtent after this frame
  std::uint64_t pixelSamples = 0;
};

// A screenshot writes both images: the one named, and the other beside it (or at `pngOverride`).
struct ScreenshotPaths {
  std::string exr;
  std::string png;
};
ScreenshotPaths screenshotPaths(const std::string& named, const std::string& pngOverride);

// One denoised image the viewer showed (viewer_denoise.cpp), as the benchmark sees it.
struct DenoiseRecord {
  std::uint32_t spp = 0;          // of the image denoised
  double startSeconds = 0.0;      // when its accumulation was read (since the loop started)
  double shownSeconds = 0.0;      // when the display pass was pointed at the result
};

struct ViewerReport {
  std::string device;
  std::string driver;
  glm::uvec2 fullExtent{0};
  std::vector<FrameRecord> frames;
  std::vector<DenoiseRecord> denoised;
  std::uint32_t spp = 0;
};

// Opens the window, runs until it is closed (or the automation ends) and returns what happened. Throws
// Error(kExitNoDevice) without a capable device, Error(kExitFailure) without an X11 display.
ViewerReport runViewer(const Scene& scene, const ViewerOptions& options);

}  // namespace raylab
