// `raylab bench`: benchmarks that print machine-independent ratios where they can, and absolute figures with
// the driver (Mesa, LLVM) and core count recorded. Benchmarks are not tests: they measure, they do not assert.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_line/cli.h"
#include "bench_commands.h"
#include "brdf_params/material_params.h"
#include "commands.h"
#include "session/gpu_session.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "builtin_scenes/default_scene.h"
#include "render/gpu_scene.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/timer.h"

namespace raylab {

namespace {

struct VariantTiming {
  std::string name;
  Backend backend = Backend::kQuery;
  std::string kernel;
  double pipelineSeconds = 0.0;     // vkCreateComputePipelines or vkCreateRayTracingPipelinesKHR, SBT included
  double firstSampleSeconds = 0.0;  // the first dispatch: lavapipe compiles the kernel with LLVM here
  double perSampleSeconds = 0.0;    // steady state
};

VariantTiming timeVariant(const Device& device, const Scene& scene, RenderSettings settings, const char* name,
                          std::uint32_t samples) {
  GpuScene gpuScene = uploadScene(device, scene);
  VariantTiming timing;
  timing.name = name;
  timing.backend = settings.backend;
  const Stopwatch pipelineClock;
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  timing.pipelineSeconds = pipelineClock.seconds();
  timing.kernel = describe(renderer.kernel);
  const Stopwatch firstClock;
  renderSamples(device, renderer, 1);
  timing.firstSampleSeconds = firstClock.seconds();
  const Stopwatch steadyClock;
  renderSamples(device, renderer, samples);
  timing.perSampleSeconds = steadyClock.seconds() / samples;
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  return timing;
}

// The default scene (the showcase) with every material plain Lambert: where specialization helps most.
Scene lambertOnlyScene() {
  Scene scene = makeDefaultScene();
  scene.name = "showcase, every material Lambert";
  for (Material& material : scene.materials) material.record = lambertMaterial(previewColour(material.record));
  return scene;
}

struct KernelsOptions {
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  std::uint32_t samples = 16;
  bool json = false;
  std::string backend = "all";
  std::optional<std::uint32_t> device;
};

int benchKernels(const KernelsOptions& o) {
  const std::uint32_t width = o.width, height = o.height, samples = o.samples;
  const bool json = o.json;
  const std::string& backend = o.backend;

  // Must be set before the driver initialises its disk cache.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  GpuSession gpu(o.device, json);
  const Scene scene = lambertOnlyScene();
  std::vector<std::pair<VariantTiming, VariantTiming>> timings;  // specialised, all features; per backend
  for (Backend b : backendsToCompare(gpu.device, backend)) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.backend = b;
    const VariantTiming specialised = timeVariant(gpu.device, scene, settings, "specialised", samples);
    settings.kernel = allFeatures();
    timings.emplace_back(specialised, timeVariant(gpu.device, scene, settings, "all features", samples));
  }

  const unsigned cores = std::thread::hardware_concurrency();
  if (json) {
    nlohmann::ordered_json variants = nlohmann::ordered_json::array();
    for (const auto& [specialised, everything] : timings) {
      for (const VariantTiming* t : {&specialised, &everything}) {
        variants.push_back({{"name", t->name},
                            {"backend", backendName(t->backend)},
                            {"pipeline_s", t->pipelineSeconds},
                            {"first_sample_s", t->firstSampleSeconds},
                            {"per_sample_s", t->perSampleSeconds},
                            {"compile_ratio_to_specialised", t->firstSampleSeconds / specialised.firstSampleSeconds},
                            {"per_sample_ratio_to_specialised", t->perSampleSeconds / specialised.perSampleSeconds}});
      }
    }
    const nlohmann::ordered_json report = {{"benchmark", "kernels"}, {"device", gpu.device.report.name},
                                           {"driver", gpu.device.report.driver}, {"cores", cores},
                                           {"scene", scene.name}, {"width", width},
                                           {"height", height}, {"variants", variants}};
    std::printf("%s\n", report.dump().c_str());
    return kExitOk;
  }
  std::printf("device: %s (%s), %u cores; scene: %s, %ux%u\n", gpu.device.report.name.c_str(),
              gpu.device.report.driver.c_str(), cores, scene.name.c_str(), width, height);
  std::printf("%-9s %-14s %12s %22s %12s\n", "backend", "kernel", "pipeline", "first sample (compile)", "per sample");
  for (const auto& [specialised, everything] : timings) {
    for (const VariantTiming* t : {&specialised, &everything}) {
      std::printf("%-9s %-14s %12s %22s %12s\n", backendName(t->backend), t->name.c_str(),
                  formatSeconds(t->pipelineSeconds).c_str(), formatSeconds(t->firstSampleSeconds).c_str(),
                  formatSeconds(t->perSampleSeconds).c_str());
    }
  }
  std::printf("specialised: %s\n", timings.front().first.kernel.c_str());
  for (const auto& [specialised, everything] : timings) {
    std::printf("%s: all features / specialised: compile %.2fx, per sample %.2fx\n", backendName(specialised.backend),
                everything.firstSampleSeconds / specialised.firstSampleSeconds,
                everything.perSampleSeconds / specialised.perSampleSeconds);
  }
  if (timings.size() == 2) {
    std::printf("pipeline / query (specialised): compile %.2fx, per sample %.2fx\n",
                timings[1].first.firstSampleSeconds / timings[0].first.firstSampleSeconds,
                timings[1].first.perSampleSeconds / timings[0].first.perSampleSeconds);
  }
  return kExitOk;
}

}  // namespace

void addBenchCommands(CLI::App& raylab) {
  CLI::App* bench = addCommandGroup(
      raylab, "bench",
      "benchmarks: kernel variants, the backends against Embree, ray order, the viewer\n"
      "Benchmarks print machine-independent ratios where they can, and absolute figures with the driver (Mesa, "
      "LLVM) and core count recorded. They measure; they do not assert (docs/performance.md).");
  auto o = std::make_shared<KernelsOptions>();
  CLI::App* command = addCommand(
      *bench, "kernels",
      "the scene-specialised kernel against the all-features kernel, on each backend\n"
      "Compares the kernel specialised for a Lambert-only scene with the all-features kernel, on each backend "
      "(ray queries, ray-tracing pipeline): pipeline creation, driver compilation (the first sample) and time per "
      "sample. Mesa's shader cache is disabled for this command so that compilation is measured, not a cache hit.",
      [o] { return benchKernels(*o); });
  addImageSizeOptions(command, o->width, o->height, "image");
  addCount(command, "--spp", o->samples, "samples timed per variant after the first", 1, 4096);
  addFlag(command, "--json", o->json, "print one JSON object instead of the table");
  addBenchBackendOption(command, o->backend);
  addDeviceOption(command, o->device);
  addBenchRaysCommand(*bench);
  addBenchOrderCommand(*bench);
  addBenchViewCommand(*bench);
}

}  // namespace raylab
