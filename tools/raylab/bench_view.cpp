// `raylab bench view`: how fluid the viewer is. For each window size it opens the viewer on the default scene,
// lets the kernel compile, orbits the camera one step per frame (the frame times a user dragging the mouse
// sees, and the preview resolution that holds them), then keeps still and times how long the window takes to
// show 16 samples per pixel at full resolution. Needs an X11 display: `xvfb-run -a raylab bench view`.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_line/cli.h"
#include "bench_commands.h"
#include "builtin_scenes/load_scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "view/viewer.h"
#include "render/render_choices.h"

namespace raylab {

namespace {

struct Size {
  std::uint32_t width;
  std::uint32_t height;
};

struct ViewTiming {
  Size size;
  double firstFrameSeconds = 0.0;  // the kernel's compilation included (cold or warm shader cache)
  std::vector<double> orbitFrameSeconds;  // intervals between frames while orbiting
  double meanPreviewPixels = 0.0;
  std::uint32_t minPreviewWidth = 0, maxPreviewWidth = 0;
  double stillTo16Seconds = 0.0;   // from the first unchanged frame to the frame that completed 16 spp
  double stillToDenoisedSeconds = 0.0;  // with --denoise: from the same frame until the denoised 16 spp was shown
  double secondsPerPixelSample = 0.0;  // still frames: device trace time per pixel-sample
  double overheadSeconds = 0.0;        // shown still frames, median: device time besides tracing (display, blit, UI)
  double stillFrameSeconds = 0.0;      // still frames, median interval
  double displaySeconds = 0.0, blitSeconds = 0.0, uiSeconds = 0.0;  // shown still frames, medians
  std::uint32_t stillFrames = 0, shownStillFrames = 0;  // refinement frames to the spp, and those displayed
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(p * double(values.size() - 1) + 0.5));
  return values[index];
}

std::string loadAverage() {
  std::ifstream file("/proc/loadavg");
  std::string one, five;
  file >> one >> five;
  return one.empty() ? "unknown" : one + " (1 min), " + five + " (5 min)";
}

void appendFramesCsv(std::string* csv, Size size, const std::vector<FrameRecord>& frames, std::uint32_t stillFrame) {
  std::ostringstream file;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const FrameRecord& f = frames[i];
    file << size.width << 'x' << size.height << ',' << i << ',' << (i < stillFrame ? "moving" : "still") << ','
         << f.submitSeconds << ',' << f.completeSeconds << ',' << f.traceExtent.x << 'x' << f.traceExtent.y << ','
         << f.preview << ',' << f.spp << ',' << f.pixelSamples << ',' << f.traceSeconds << ',' << f.displaySeconds
         << ',' << f.blitSeconds << ',' << f.deviceSeconds << ',' << (f.shown ? "shown" : "unshown") << '\n';
  }
  *csv += file.str();
}

ViewTiming timeViewer(const Scene& scene, Size size, std::uint32_t warmupFrames, std::uint32_t orbitFrames,
                      float degreesPerFrame, double targetMs, std::uint32_t spp, BackendChoice backend, bool denoise,
                      std::string* csv) {
  ViewerOptions options;
  options.denoise = denoise;
  options.backend = backend;
  options.width = size.width;
  options.height = size.height;
  options.targetMs = targetMs;
  options.sppLimit = spp;
  options.exitWhenConverged = true;
  options.quiet = true;
  for (std::uint32_t i = 0; i < orbitFrames; ++i) {
    ScriptEvent event;
    event.frame = warmupFrames + i;
    event.action = ScriptAction::kOrbit;
    event.where = "bench";
    event.value = glm::vec3(degreesPerFrame, 0.0f, 0.0f);
    event.valueCount = 2;
    options.script.push_back(event);
  }
  const ViewerReport report = runViewer(scene, options);
  const std::vector<FrameRecord>& frames = report.frames;
  const std::uint32_t stillFrame = warmupFrames + orbitFrames;
  if (csv != nullptr) appendFramesCsv(csv, size, frames, stillFrame);
  if (frames.size() <= stillFrame) {
    throw Error("raylab bench view: the viewer stopped after " + std::to_string(frames.size()) + " frames");
  }

  ViewTiming timing;
  timing.size = size;
  timing.firstFrameSeconds = frames[0].completeSeconds - frames[0].submitSeconds;
  double previewPixels = 0.0;
  timing.minPreviewWidth = UINT32_MAX;
  // The first orbit frame's interval includes the still frames before it; measure from the second.
  for (std::uint32_t i = warmupFrames + 1; i < stillFrame; ++i) {
    timing.orbitFrameSeconds.push_back(frames[i].submitSeconds - frames[i - 1].submitSeconds);
    previewPixels += double(frames[i].traceExtent.x) * frames[i].traceExtent.y;
    timing.minPreviewWidth = std::min(timing.minPreviewWidth, frames[i].traceExtent.x);
    timing.maxPreviewWidth = std::max(timing.maxPreviewWidth, frames[i].traceExtent.x);
  }
  timing.meanPreviewPixels = previewPixels / std::max<std::size_t>(1, timing.orbitFrameSeconds.size());

  const double stillStart = frames[stillFrame].submitSeconds;
  double traceSeconds = 0.0;
  double pixelSamples = 0.0;
  std::vector<double> overheads, intervals, displays, blits, uis;
  for (std::size_t i = stillFrame; i < frames.size(); ++i) {
    const FrameRecord& frame = frames[i];
    if (!frame.preview) {
      traceSeconds += frame.traceSeconds;
      pixelSamples += double(frame.pixelSamples);
      intervals.push_back(frame.submitSeconds - frames[i - 1].submitSeconds);
      ++timing.stillFrames;
    }
    if (!frame.preview && frame.shown) {
      overheads.push_back(frame.deviceSeconds - frame.traceSeconds);
      displays.push_back(frame.displaySeconds);
      blits.push_back(frame.blitSeconds);
      uis.push_back(frame.deviceSeconds - frame.traceSeconds - frame.displaySeconds - frame.blitSeconds);
      ++timing.shownStillFrames;
    }
    if (!frame.preview && frame.traceExtent == report.fullExtent && frame.spp >= spp) {
      timing.stillTo16Seconds = frame.completeSeconds - stillStart;
      break;
    }
  }
  for (const DenoiseRecord& record : report.denoised) {
    if (record.startSeconds >= stillStart && record.spp >= spp) {
      timing.stillToDenoisedSeconds = record.shownSeconds - stillStart;
      break;
    }
  }
  if (denoise && timing.stillToDenoisedSeconds == 0.0) {
    throw Error("raylab bench view: the viewer ended before it showed the denoised image at " + std::to_string(spp) +
                " spp");
  }
  timing.secondsPerPixelSample = pixelSamples > 0.0 ? traceSeconds / pixelSamples : 0.0;
  timing.overheadSeconds = percentile(overheads, 0.5);
  timing.stillFrameSeconds = percentile(intervals, 0.5);
  timing.displaySeconds = percentile(displays, 0.5);
  timing.blitSeconds = percentile(blits, 0.5);
  timing.uiSeconds = percentile(uis, 0.5);
  return timing;
}

struct ViewBenchOptions {
  std::uint32_t warmupFrames = 8;
  std::uint32_t orbitFrames = 60;
  std::uint32_t spp = 16;
  float targetMs = 50.0f;
  float degrees = 0.0f;
  bool json = false;
  bool denoise = false;
  std::string scenePath;
  std::string csvPath;
  std::string backend{kBackendOption.defaultValue};
};

int benchView(const ViewBenchOptions& o) {
  const std::uint32_t warmupFrames = o.warmupFrames, orbitFrames = o.orbitFrames, spp = o.spp;
  const float targetMs = o.targetMs;
  const bool json = o.json;
  const std::string& scenePath = o.scenePath;
  const std::string& csvPath = o.csvPath;
  const std::string& backend = o.backend;
  float degrees = o.degrees;
  if (degrees == 0.0f) degrees = 360.0f / float(orbitFrames);

  const Scene scene = loadScene({scenePath, ""});
  if (!csvPath.empty()) checkOutputPath(csvPath, "--frames-csv");
  std::string csv;
  const std::string loadBefore = loadAverage();
  std::vector<ViewTiming> timings;
  for (const Size size : {Size{640, 360}, Size{1280, 720}}) {
    timings.push_back(timeViewer(scene, size, warmupFrames, orbitFrames, degrees, targetMs, spp,
                                 parseBackendChoice(backend, "raylab bench view: --backend"), o.denoise,
                                 csvPath.empty() ? nullptr : &csv));
  }
  if (!csvPath.empty()) writeFileAtomically(csvPath, csv);
  const std::string loadAfter = loadAverage();
  const unsigned cores = std::thread::hardware_concurrency();

  if (json) {
    nlohmann::ordered_json sizes = nlohmann::ordered_json::array();
    for (const ViewTiming& t : timings) {
      sizes.push_back({{"width", t.size.width},
                       {"height", t.size.height},
                       {"first_frame_s", t.firstFrameSeconds},
                       {"orbit_median_ms", 1e3 * percentile(t.orbitFrameSeconds, 0.5)},
                       {"orbit_p90_ms", 1e3 * percentile(t.orbitFrameSeconds, 0.9)},
                       {"orbit_max_ms", 1e3 * percentile(t.orbitFrameSeconds, 1.0)},
                       {"preview_mean_pixels", t.meanPreviewPixels},
                       {"still_to_spp_s", t.stillTo16Seconds},
                       {"still_to_denoised_s", o.denoise ? nlohmann::ordered_json(t.stillToDenoisedSeconds) : nullptr},
                       {"still_frame_ms", 1e3 * t.stillFrameSeconds},
                       {"overhead_ms", 1e3 * t.overheadSeconds},
                       {"still_frames", t.stillFrames},
                       {"shown_still_frames", t.shownStillFrames},
                       {"ns_per_pixel_sample", 1e9 * t.secondsPerPixelSample}});
    }
    const nlohmann::ordered_json report = {{"benchmark", "view"}, {"scene", scene.name},   {"backend", backend},
                                           {"cores", cores},      {"target_ms", targetMs}, {"spp", spp},
                                           {"load_before", loadBefore}, {"load_after", loadAfter}, {"sizes", sizes}};
    std::printf("%s\n", report.dump().c_str());
    return kExitOk;
  }
  std::printf("scene: %s; backend %s; %u cores; target %.0f ms/frame; load average %s before, %s after\n",
              scene.name.c_str(), backend.c_str(), cores, targetMs, loadBefore.c_str(), loadAfter.c_str());
  std::printf("%-10s %12s %24s %22s %16s %22s %13s\n", "window", "first frame", "orbit ms/frame p50/p90/max",
              "preview (mean, widths)", "still to spp", "still ms/frame (other)", "ns/pixel-spp");
  for (const ViewTiming& t : timings) {
    char size[32], orbit[48], preview[48], still[32];
    std::snprintf(size, sizeof size, "%ux%u", t.size.width, t.size.height);
    std::snprintf(orbit, sizeof orbit, "%.1f / %.1f / %.1f", 1e3 * percentile(t.orbitFrameSeconds, 0.5),
                  1e3 * percentile(t.orbitFrameSeconds, 0.9), 1e3 * percentile(t.orbitFrameSeconds, 1.0));
    std::snprintf(preview, sizeof preview, "%.0f px, %u-%u", t.meanPreviewPixels, t.minPreviewWidth, t.maxPreviewWidth);
    std::snprintf(still, sizeof still, "%u spp in %.2f s", spp, t.stillTo16Seconds);
    char stillFrame[32];
    std::snprintf(stillFrame, sizeof stillFrame, "%.1f (%.1f)", 1e3 * t.stillFrameSeconds, 1e3 * t.overheadSeconds);
    std::printf("%-10s %10.2f s %24s %22s %16s %22s %13.0f\n", size, t.firstFrameSeconds, orbit, preview, still,
                stillFrame, 1e9 * t.secondsPerPixelSample);
  }
  for (const ViewTiming& t : timings) {
    if (o.denoise) {
      std::printf("%ux%u denoised at %u spp shown %.2f s after the camera stopped\n", t.size.width, t.size.height,
                  spp, t.stillToDenoisedSeconds);
    }
  }
  for (const ViewTiming& t : timings) {
    std::printf("%ux%u still frames: %u, %u of them shown; shown frames, device ms: display pass %.1f, blit %.1f, "
                "UI %.1f\n",
                t.size.width, t.size.height, t.stillFrames, t.shownStillFrames, 1e3 * t.displaySeconds,
                1e3 * t.blitSeconds, 1e3 * t.uiSeconds);
  }
  std::printf("still ms/frame (other): interval between still frames, and the device time per shown frame that\n"
              "is not tracing (display pass, blit, UI); between shown frames the viewer only traces. First frame\n"
              "> 0.5 s: the shader cache was cold.\n");
  return kExitOk;
}

}  // namespace

void addBenchViewCommand(CLI::App& bench) {
  auto o = std::make_shared<ViewBenchOptions>();
  CLI::App* command = addCommand(
      bench, "view",
      "the viewer's frame times while orbiting and its time to 16 spp (needs X11)\n"
      "Times the viewer on the default scene at 640x360 and 1280x720: frame times while the camera orbits one "
      "step per frame, and the time from the last change until the window shows --spp samples per pixel at full "
      "resolution. Needs an X11 display (headless: xvfb-run -a). The first frames (the driver compiling the "
      "kernels) are not timed.",
      [o] { return benchView(*o); });
  addCount(command, "--warmup", o->warmupFrames, "frames before the orbit starts", 1, 1000);
  addCount(command, "--orbit-frames", o->orbitFrames, "frames of orbiting", 2, 100000);
  addNumber(command, "--degrees", o->degrees, "orbit step per frame (0: a full turn, back to the scene's view)", 0.0f,
            90.0f);
  addNumber(command, "--target-ms", o->targetMs, "the viewer's frame-time target", 5.0f, 1000.0f);
  addCount(command, "--spp", o->spp, "samples per pixel to reach when still", 1, 4096);
  addText(command, "--scene", o->scenePath, "FILE", "a glTF scene instead of the built-in one");
  addFlag(command, "--json", o->json, "print one JSON object instead of the table");
  addFlag(command, "--denoise", o->denoise,
          "with the viewer's denoised view on: also time until the denoised image at --spp is shown");
  addText(command, "--frames-csv", o->csvPath, "FILE",
          "also write every frame (size, index, phase, submit and completion time, traced size, preview, spp, "
          "pixel-samples, device seconds of tracing, display, blit and the whole frame) to FILE");
  addBackendOption(command, o->backend);
}

}  // namespace raylab
