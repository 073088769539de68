// `raylab render`: offscreen frame capture to OpenEXR (linear) and PNG (tone-mapped), for scripts and CI.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_line/cli.h"
#include "commands.h"
#include "denoise/denoise.h"
#include "session/gpu_session.h"
#include "image/image.h"
#include "render/renderer.h"
#include "builtin_scenes/load_scene.h"
#include "render/gpu_scene.h"
#include "util/error.h"
#include "shared/features.h"
#include "util/atomic_file.h"
#include "util/progress.h"
#include "util/timer.h"
#include "view_logic/compare_spec.h"
#include "render/render_choices.h"

namespace raylab {

namespace {

struct RenderOptions {
  SceneRequest request;
  RenderSettings settings;
  std::uint32_t spp = 16;
  std::string exrPath;
  std::string pngPath;
  std::string reportPath;
  std::string heatmapPath;
  float exposure = 0.0f;
  std::string toneMap = "clamp";
  bool noAntialiasing = false;
  bool noExr = false;
  bool noPng = false;
  bool stats = false;
  bool allFeatures = false;
  bool denoise = false;
  std::string denoiseQuality;
  // The render options' values as given; their defaults come from util/render_options.h (addChoiceOption).
  std::string fresnel;
  std::string integrator;
  std::string sampling;
  std::string backend;
  std::string schedule;
  std::string guiding;
  std::optional<std::uint32_t> device;
  std::vector<std::string> materials;  // --material MATERIAL=MODEL[:k=v,...]
};

// The figures the command prints, for scripts (tools/speed_vs_error.py): seconds, counts and what was rendered.
struct RenderReport {
  double accelerationSeconds = 0.0;
  double firstSampleSeconds = 0.0;  // kernel compilation included
  double steadySeconds = 0.0;       // samples 2..spp
  double steadyCpuSeconds = 0.0;    // the same samples in CPU time of the process (lavapipe's threads included)
  double perSampleSeconds = 0.0;
  double raysPerSecond = 0.0;
  double denoiseSeconds = 0.0;  // with --denoise
};

// Where --denoise writes beside `path` (out/x.exr): out/x.denoised.exr, out/x.albedo.exr, ...; "" for "".
std::string besidePath(const std::string& path, const std::string& kind) {
  if (path.empty()) return "";
  std::filesystem::path sibling(path);
  const std::string extension = sibling.extension().string();
  sibling.replace_extension("." + kind + extension);
  return sibling.string();
}

void writeReport(const std::string& path, const RenderOptions& o, const Scene& scene, const GpuScene& gpuScene,
                 const Device& device, const Renderer& renderer, const RenderReport& r) {
  const nlohmann::ordered_json report = {
      {"scene", scene.name},
      {"scene_file", o.request.path},
      {"width", o.settings.width},
      {"height", o.settings.height},
      {"spp", o.spp},
      {"seed", o.settings.seed},
      {"max_depth", o.settings.maxDepth},
      {"fresnel", o.fresnel},
      {"integrator", std::string(integratorName(renderer.kernel.integrator))},
      {"sampling", o.sampling},
      {"dropped_samples", renderer.droppedSamples},
      {"all_features", o.allFeatures},
      {"kernel", describe(renderer.kernel)},
      {"backend", backendName(renderer.trace.backend)},
      {"schedule", renderer.wavefrontActive ? "wavefront" : "megakernel"},
      {"guiding", o.guiding},
      {"guide", renderer.guide.mode == Guiding::kOff
                    ? nlohmann::ordered_json(nullptr)
                    : nlohmann::ordered_json{
                          {"updates", renderer.guide.summary.updates},
                          {"cells", renderer.guide.summary.cellsGuided},
                          {"moment_ratio", renderer.guide.summary.decided
                                               ? nlohmann::ordered_json(renderer.guide.summary.momentRatio)
                                               : nlohmann::ordered_json(nullptr)},
                          {"guiding", renderer.guide.summary.guiding}}},
      {"device", device.report.name},
      {"driver", device.report.driver},
      {"triangles", gpuScene.triangleCount},
      {"spheres", gpuScene.sphereCount},
      {"lights", gpuScene.punctualLightCount},
      {"acceleration_build_s", r.accelerationSeconds},
      {"first_sample_s", r.firstSampleSeconds},
      {"steady_samples", o.spp - 1},
      {"steady_s", r.steadySeconds},
      {"per_sample_s", r.perSampleSeconds},
      {"steady_cpu_s", r.steadyCpuSeconds},
      {"cpu_per_sample_s", o.spp > 1 ? nlohmann::ordered_json(r.steadyCpuSeconds / (o.spp - 1)) : nullptr},
      {"rays", {{"total", renderer.rays.total()},
                {"primary", renderer.rays.primary},
                {"shadow", renderer.rays.shadow},
                {"secondary", renderer.rays.secondary}}},
      {"rays_per_s", r.raysPerSecond},
      {"lane_utilisation", renderer.rays.groupSegments > 0
                               ? nlohmann::ordered_json(laneUtilisation(renderer.rays, device.subgroupSize))
                               : nullptr},
      {"exr", o.exrPath},
      {"png", o.pngPath},
      {"denoise", o.denoise ? nlohmann::ordered_json{{"quality", o.denoiseQuality},
                                                     {"seconds", r.denoiseSeconds},
                                                     {"exr", besidePath(o.exrPath, "denoised")},
                                                     {"png", besidePath(o.pngPath, "denoised")},
                                                     {"albedo", besidePath(o.exrPath, "albedo")},
                                                     {"normal", besidePath(o.exrPath, "normal")}}
                            : nlohmann::ordered_json(nullptr)},
  };
  writeFileAtomically(path, report.dump(2) + "\n");
}

// The files of a render, each written atomically, in order. When one fails after another was written, the message
// says which files were written and which was not, so nothing is taken for done that is not.
class ImageWriter {
 public:
  void attempt(const std::string& path, const std::function<void()>& write) {
    if (path.empty()) return;
    try {
      write();
    } catch (const Error& error) {
      throw Error(std::string(error.what()) + writtenSoFar(), error.exitCode());
    }
    written_.push_back(path);
    std::printf("wrote %s\n", path.c_str());
  }
  // "; no file was written" or "; written before the failure: A B".
  std::string writtenSoFar() const {
    std::string text = written_.empty() ? "; no file was written" : "; written before the failure:";
    for (const std::string& done : written_) text += " " + done;
    return text;
  }

 private:
  std::vector<std::string> written_;
};

void writeImages(const RenderOptions& o, const Image& image, ImageWriter& writer) {
  writer.attempt(o.exrPath, [&] { writeExr(o.exrPath, image); });
  writer.attempt(o.pngPath, [&] { writePng(o.pngPath, image, o.exposure, parseToneMap(o.toneMap)); });
}

// --denoise's files beside the raw ones: the denoised image, and the first-hit albedo and normal it was guided by.
void writeDenoisedImages(const RenderOptions& o, const Image& denoised, const AuxiliaryImages& guides,
                         ImageWriter& writer) {
  const std::string exr = besidePath(o.exrPath, "denoised"), png = besidePath(o.pngPath, "denoised");
  writer.attempt(exr, [&] { writeExr(exr, denoised); });
  writer.attempt(png, [&] { writePng(png, denoised, o.exposure, parseToneMap(o.toneMap)); });
  const std::string albedo = besidePath(o.exrPath, "albedo"), normal = besidePath(o.exrPath, "normal");
  writer.attempt(albedo, [&] { writeExr(albedo, guides.albedo); });
  writer.attempt(normal, [&] { writeExr(normal, guides.normal); });
}

// The render the options ask for; `o` by value: defaults are filled in.
void render(RenderOptions o) {
  o.settings.jitter = !o.noAntialiasing;
  o.settings.aovs = o.denoise;
  const DenoiseQuality quality = parseDenoiseQuality(o.denoiseQuality, "raylab render: --denoise-quality");
  // The outputs --denoise adds beside --out and --png; none without it.
  const auto denoisedOutput = [&o](const std::string& path, const char* kind) {
    return o.denoise ? besidePath(path, kind) : std::string();
  };
  if (!o.exrPath.empty() && o.noExr) throw Error("raylab render: --out and --no-exr contradict each other", kExitUsage);
  if (!o.pngPath.empty() && o.noPng) throw Error("raylab render: --png and --no-png contradict each other", kExitUsage);
  if (!o.exrPath.empty()) requireExtension("raylab render", "--out", o.exrPath, ".exr");
  if (!o.pngPath.empty()) requireExtension("raylab render", "--png", o.pngPath, ".png");
  if (!o.reportPath.empty()) requireExtension("raylab render", "--report", o.reportPath, ".json");
  if (!o.heatmapPath.empty()) requireExtension("raylab render", "--heatmap", o.heatmapPath, ".png");
  o.settings.heatmap = !o.heatmapPath.empty();
  // Each output has its own default, so giving one never suppresses the other.
  const SceneRequest& request = o.request;
  if (o.exrPath.empty() && !o.noExr) o.exrPath = "out/" + sceneName(request) + ".exr";
  if (o.pngPath.empty() && !o.noPng) o.pngPath = "out/" + sceneName(request) + ".png";
  if (o.exrPath.empty() && o.pngPath.empty() && o.reportPath.empty() && o.heatmapPath.empty()) {
    throw Error("raylab render: --no-exr and --no-png leave nothing to write (add --report to time a render)",
                kExitUsage);
  }
  // Before any work: a render is never thrown away because its output cannot be written, and no output
  // replaces another.
  const std::string heatmapExr =
      o.heatmapPath.empty() ? "" : std::filesystem::path(o.heatmapPath).replace_extension(".exr").string();
  checkDistinctOutputs("raylab render", {{"--out", o.exrPath},
                                         {"--png", o.pngPath},
                                         {"--report", o.reportPath},
                                         {"--heatmap", o.heatmapPath},
                                         {"--heatmap (its .exr)", heatmapExr},
                                         {"--denoise (the denoised .exr)", denoisedOutput(o.exrPath, "denoised")},
                                         {"--denoise (the denoised .png)", denoisedOutput(o.pngPath, "denoised")},
                                         {"--denoise (the albedo .exr)", denoisedOutput(o.exrPath, "albedo")},
                                         {"--denoise (the normal .exr)", denoisedOutput(o.exrPath, "normal")}});
  if (!o.exrPath.empty()) checkOutputPath(o.exrPath, "--out");
  if (!o.pngPath.empty()) checkOutputPath(o.pngPath, "--png");
  if (!o.reportPath.empty()) checkOutputPath(o.reportPath, "--report");
  if (!o.heatmapPath.empty()) {
    checkOutputPath(o.heatmapPath, "--heatmap");
    checkOutputPath(heatmapExr, "--heatmap");
  }
  for (const char* kind : {"denoised", "albedo", "normal"}) {
    if (!denoisedOutput(o.exrPath, kind).empty()) checkOutputPath(denoisedOutput(o.exrPath, kind), "--denoise");
  }
  if (!denoisedOutput(o.pngPath, "denoised").empty()) checkOutputPath(denoisedOutput(o.pngPath, "denoised"), "--denoise");
  if (o.denoise) {
    // Before any work: without the library --denoise fails now (exit 2, how to install), not after the render.
    if (o.exrPath.empty() && o.pngPath.empty()) {
      throw Error("raylab render: --denoise writes beside the EXR or PNG, and --no-exr --no-png leave neither",
                  kExitUsage);
    }
    const std::string library = loadDenoiser();
    std::fprintf(stderr, "raylab render: denoising with Open Image Denoise from %s\n", library.c_str());
  }

  o.request.maxBufferBytes = deviceBufferLimit(o.device);  // an environment too large is refused from its header
  Scene scene = loadScene(request);
  for (const std::string& text : o.materials) {
    const CompareSpec spec = parseCompareSpec(text, scene, "raylab render: --material");
    scene.materials[spec.material].record = spec.record;
  }
  KernelOptions kernel;
  kernel.integrator = parseIntegratorChoice(o.integrator, "raylab render: --integrator");
  kernel.sampling = parseSampling(o.sampling, "raylab render: --sampling");
  kernel.schlickFresnel = parseSchlickFresnel(o.fresnel, "raylab render: --fresnel");
  kernel.allFeatures = o.allFeatures;
  o.settings.kernel = kernelFor(scene, kernel);

  GpuSession gpu(o.device);
  o.settings.backend = chooseBackend(gpu.device, parseBackendChoice(o.backend, "raylab render: --backend"));
  o.settings.schedule = parseSchedule(o.schedule, "raylab render: --schedule");
  o.settings.guiding = parseGuiding(o.guiding, "raylab render: --guiding");
  checkImageSize(gpu.device, o.settings.width, o.settings.height);
  GpuScene gpuScene = uploadScene(gpu.device, scene);
  Renderer renderer;
  try {
    const Stopwatch firstSampleClock;
    renderer = createRenderer(gpu.device, gpuScene, scene, o.settings);
    // The driver compiles the kernel at its first dispatch: tens of seconds on a CPU device for a textured or
    // path-traced scene, which must not pass in silence (nor count in the first rate).
    std::fprintf(stderr, "raylab render: compiling the render kernel (%s); the first sample waits for it\n",
                 describe(renderer.kernel).c_str());
    ProgressLine progress("raylab render", o.spp);
    renderSamples(gpu.device, renderer, 1);  // includes the kernel's compilation by the driver
    const double firstSampleSeconds = firstSampleClock.seconds();
    progress.warmedUp(renderer.samplesDone, renderer.rays.total());

    // Later samples go in submissions of about a quarter second: progress stays live, overhead stays low.
    const Stopwatch steadyClock;
    const CpuStopwatch steadyCpuClock;
    const RayCounts firstRays = renderer.rays;
    std::uint32_t batch = 1;
    while (renderer.samplesDone < o.spp) {
      const Stopwatch batchClock;
      const std::uint32_t samples = std::min(batch, o.spp - renderer.samplesDone);
      renderSamples(gpu.device, renderer, samples);
      progress.update(renderer.samplesDone, renderer.rays.total());
      const double perSample = batchClock.seconds() / samples;
      batch = std::clamp<std::uint32_t>(static_cast<std::uint32_t>(0.25 / std::max(perSample, 1e-6)), 1, 256);
    }
    progress.finish();
    const double steadySeconds = steadyClock.seconds();
    const double steadyCpuSeconds = steadyCpuClock.seconds();

    const Image image = readImage(gpu.device, renderer);
    checkFinite(image, "raylab render");  // before any file: none is written when one would be refused
    ImageWriter writer;
    writeImages(o, image, writer);  // the raw image first: a denoiser that fails loses nothing
    double denoiseSeconds = 0.0;
    if (o.denoise) {
      const AuxiliaryImages guides = readAuxiliaryImages(gpu.device, renderer);
      const Stopwatch denoiseClock;
      Image denoised;
      try {
        denoised = denoise(image, &guides, quality);
      } catch (const Error& error) {
        throw Error(std::string(error.what()) + writer.writtenSoFar(), error.exitCode());
      }
      denoiseSeconds = denoiseClock.seconds();
      writeDenoisedImages(o, denoised, guides, writer);
    }
    if (!o.heatmapPath.empty()) {
      writeCostMap(o.heatmapPath, readCostMap(gpu.device, renderer), scene.name);
      std::printf("wrote %s\nwrote %s\n", o.heatmapPath.c_str(),
                  std::filesystem::path(o.heatmapPath).replace_extension(".exr").c_str());
    }

    const std::uint32_t steadySamples = o.spp - 1;
    const double perSample = steadySamples > 0 ? steadySeconds / steadySamples : firstSampleSeconds;
    const std::uint64_t steadyRays = renderer.rays.total() - firstRays.total();
    const double raysPerSecond = steadySamples > 0 && steadySeconds > 0.0
                                     ? steadyRays / steadySeconds
                                     : renderer.rays.total() / std::max(firstSampleSeconds, 1e-9);
    std::printf("scene: %s, %ux%u, %u spp, %llu triangles, %u sphere%s, %u light%s\n", scene.name.c_str(),
                o.settings.width, o.settings.height, o.spp,
                static_cast<unsigned long long>(gpuScene.triangleCount), gpuScene.sphereCount,
                gpuScene.sphereCount == 1 ? "" : "s", gpuScene.punctualLightCount,
                gpuScene.punctualLightCount == 1 ? "" : "s");
    std::printf("acceleration structures: %s\n", formatSeconds(gpuScene.accelerationBuildSeconds).c_str());
    if (o.stats) {
      std::printf("kernel: %s\n", describe(renderer.kernel).c_str());
      std::printf("backend: %s; schedule: %s\n", backendName(renderer.trace.backend),
                  renderer.wavefrontActive ? "wavefront" : "megakernel");
      if (renderer.rays.groupSegments > 0) {
        std::printf("lane utilisation: %.1f%% of the %u-lane groups' path segments\n",
                    100.0 * laneUtilisation(renderer.rays, gpu.device.subgroupSize), gpu.device.subgroupSize);
      }
    }
    if (renderer.guide.mode != Guiding::kOff) std::printf("%s\n", describeGuide(renderer.guide).c_str());
    if (o.stats || renderer.droppedSamples > 0) {
      std::printf("dropped samples (NaN or Inf): %llu\n", static_cast<unsigned long long>(renderer.droppedSamples));
    }
    if (o.denoise) {
      std::printf("denoised: %s (Open Image Denoise, %s quality, with first-hit albedo and normal)\n",
                  formatSeconds(denoiseSeconds).c_str(), o.denoiseQuality.c_str());
    }
    std::printf("first sample: %s (kernel compilation included)\n", formatSeconds(firstSampleSeconds).c_str());
    std::printf("per sample: %s\n", formatSeconds(perSample).c_str());
    std::printf("rays: %s (primary %s, shadow %s, secondary %s), %s\n",
                formatCount(double(renderer.rays.total()), "").c_str(),
                formatCount(double(renderer.rays.primary), "").c_str(),
                formatCount(double(renderer.rays.shadow), "").c_str(),
                formatCount(double(renderer.rays.secondary), "").c_str(), formatCount(raysPerSecond, "rays/s").c_str());
    if (!o.reportPath.empty()) {
      writeReport(o.reportPath, o, scene, gpuScene, gpu.device, renderer,
                  {gpuScene.accelerationBuildSeconds, firstSampleSeconds, steadySeconds, steadyCpuSeconds, perSample,
                   raysPerSecond, denoiseSeconds});
      std::printf("wrote %s\n", o.reportPath.c_str());
    }
  } catch (...) {
    destroyRenderer(gpu.device, renderer);
    destroyGpuScene(gpu.device, gpuScene);
    throw;
  }
  destroyRenderer(gpu.device, renderer);
  destroyGpuScene(gpu.device, gpuScene);
}

}  // namespace

void addRenderCommand(CLI::App& raylab) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* command = addCommand(
      raylab, "render",
      "render a scene offscreen to OpenEXR and PNG\n"
      "Renders SCENE (glTF 2.0) or, without SCENE, the built-in default scene, and writes a linear OpenEXR image "
      "and a tone-mapped sRGB PNG. The same command gives a bit-identical image on the same device. Without --out "
      "and --png it writes out/<scene>.exr and out/<scene>.png.",
      [o] {
        render(*o);
        return kExitOk;
      });
  addSceneOptions(command, o->request);
  addTextList(command, "--material", o->materials, "MATERIAL=MODEL[:k=v,...]",
              "render MATERIAL as MODEL with these parameters (RGB as r/g/b; the others take the model's defaults); "
              "the right side of `raylab view --compare` with the same text");
  addImageSizeOptions(command, o->settings.width, o->settings.height, "image");
  addCount(command, "--spp", o->spp, "samples per pixel", 1, kMaxSamplesPerPixel);
  addSampleOptions(command, o->settings);
  addFlag(command, "--no-aa", o->noAntialiasing, "sample pixel centres only (no anti-aliasing jitter)");
  addText(command, "--out", o->exrPath, "FILE.exr",
          "write the linear image here (OpenEXR, float32 RGBA; default out/<scene>.exr)");
  addText(command, "--png", o->pngPath, "FILE.png", "write the tone-mapped image here (sRGB, 8-bit; default out/<scene>.png)");
  addFlag(command, "--no-exr", o->noExr, "write no OpenEXR image");
  addFlag(command, "--no-png", o->noPng, "write no PNG image");
  addFlag(command, "--denoise", o->denoise,
          "also write the image denoised by Intel Open Image Denoise (from PyPI's pyoidn, loaded at run time), "
          "guided by the first-hit albedo and normal: FILE.denoised.exr and FILE.denoised.png beside --out and "
          "--png, and the guides as FILE.albedo.exr and FILE.normal.exr beside --out");
  addChoiceOption(command, kDenoiseQualityOption, o->denoiseQuality);
  addText(command, "--heatmap", o->heatmapPath, "FILE.png",
          "also write the cost of every pixel (device clock ticks per sample, VK_KHR_shader_clock) in false colour, "
          "and its raw values as FILE.exr; clocks the megakernel on ray queries");
  addText(command, "--report", o->reportPath, "FILE.json",
          "also write the printed figures (times, rays, kernel, device) here as JSON, for scripts");
  addToneOptions(command, o->exposure, o->toneMap, "the PNG");
  addIntegratorOption(command, o->integrator);
  addChoiceOption(command, kSamplingOption, o->sampling);
  addFlag(command, "--stats", o->stats,
          "print the kernel variant (models, features), the backend and schedule, and the lane utilisation");
  addFlag(command, "--all-features", o->allFeatures, "compile every model and feature in, not only what the scene uses");
  addChoiceOption(command, kFresnelOption, o->fresnel);
  addBackendOption(command, o->backend);
  addChoiceOption(command, kScheduleOption, o->schedule);
  addChoiceOption(command, kGuidingOption, o->guiding);
  addDeviceOption(command, o->device);
}

}  // namespace raylab
