// `raylab bench order`: what coherence within lavapipe's groups of 8 lanes is worth, measured before any
// reordering is built (issue 12). The same bounce rays traced in several orders (as generated, shuffled, by
// direction octant, by Morton keys of origin and direction), each against Embree 3 single rays in the same
// order; and the BRDF library evaluated with 8 models mixed within every group of 8 lanes against sorted by model.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_line/cli.h"
#include "bench/bench_scenes.h"
#include "bench/embree_tracer.h"
#include "bench/ray_order.h"
#include "bench/ray_sets.h"
#include "bench_commands.h"
#include "brdf_eval/device_evaluator.h"
#include "session/gpu_session.h"
#include "render/ray_probe.h"
#include "render/gpu_scene.h"
#include "brdf_params/material_params.h"
#include "shared/features.h"
#include "util/error.h"
#include "util/timer.h"

namespace raylab {

namespace {

// Best of `repeat` runs of `work`, in CPU seconds of the whole process (lavapipe's and Embree's threads).
template <class Work>
double bestCpuSeconds(std::uint32_t repeat, const Work& work) {
  double best = 1e30;
  for (std::uint32_t i = 0; i < repeat; ++i) {
    const CpuStopwatch cpu;
    work();
    best = std::min(best, cpu.seconds());
  }
  return best;
}

struct OrderResult {
  std::string scene;
  RayOrder order = RayOrder::kGenerated;
  std::size_t rays = 0;
  double raylabSeconds = 0.0;      // closest hit with the surface reconstructed
  double raylabBareSeconds = 0.0;  // closest hit distance and ids only
  double embreeSeconds = 0.0;      // Embree, one thread, single rays
};

struct ShadingResult {
  std::string layout;
  std::size_t cases = 0;
  double seconds = 0.0;  // the dispatch, wall clock, best of the repeats
};

double mrays(std::size_t rays, double seconds) { return seconds > 0.0 ? rays / seconds / 1e6 : 0.0; }

// Cases of every BRDF model with a density (delta BSDFs are a separate path of the evaluator) at random
// directions about +Z.
std::vector<gpu::BrdfEvalCase> shadingCases(std::size_t count, bool sortedByModel) {
  std::vector<std::uint32_t> models;
  for (const ModelInfo& model : allModels()) {
    if (!isDeltaOnly(model)) models.push_back(model.id);
  }
  std::mt19937 generator(7);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const auto direction = [&] {
    glm::vec3 v(uniform(generator), uniform(generator), std::abs(uniform(generator)) + 0.05f);
    return glm::normalize(v);
  };
  std::vector<gpu::BrdfEvalCase> cases(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Mixed: lane i of every group of 8 has model i % 8. Sorted: blocks of count / 8 cases per model.
    const std::size_t model = sortedByModel ? i * models.size() / count : i % models.size();
    cases[i].material = defaultRecord(models[model]);
    cases[i].wi = direction();
    cases[i].wo = direction();
    cases[i].n = glm::vec3(0.0f, 0.0f, 1.0f);
    cases[i].t = glm::vec3(1.0f, 0.0f, 0.0f);
  }
  return cases;
}

struct OrderOptions {
  std::uint32_t size = 512;
  std::uint32_t repeat = 3;
  std::uint32_t shadingCount = 1u << 18;
  std::string only;
  bool json = false;
  std::optional<std::uint32_t> device;
};

int benchOrder(const OrderOptions& o) {
  const std::uint32_t size = o.size, repeat = o.repeat, shadingCount = o.shadingCount;
  const std::string& only = o.only;
  const bool json = o.json;

  GpuSession gpu(o.device, json);
  std::vector<OrderResult> results;
  for (const BenchSceneInfo& info : allBenchScenes()) {
    if (!only.empty() && only != info.key) continue;
    const Scene scene = makeBenchScene(info.kind);
    GpuScene gpuScene = uploadScene(gpu.device, scene);
    EmbreeTracer embree = createEmbreeTracer(scene, 1);
    const std::vector<gpu::ProbeRay> primary = primaryRays(scene, size, size);
    RayProbe probe = createRayProbe(gpu.device, gpuScene, static_cast<std::uint32_t>(primary.size()));
    const std::vector<gpu::ProbeHit> primaryHits = traceRays(gpu.device, probe, primary);
    const std::vector<gpu::ProbeRay> bounce = bounceRays(primaryHits, primary);
    const auto count = static_cast<std::uint32_t>(bounce.size());
    for (RayOrder order : allRayOrders()) {
      const std::vector<gpu::ProbeRay> rays = permuted<gpu::ProbeRay>(bounce, rayPermutation(bounce, order));
      OrderResult r;
      r.scene = scene.name;
      r.order = order;
      r.rays = rays.size();
      traceRays(gpu.device, probe, rays, gpu::kProbeClosest);  // uploads them
      r.raylabSeconds = bestCpuSeconds(repeat, [&] { timeTraceRays(gpu.device, probe, count, gpu::kProbeClosest, 1); });
      r.raylabBareSeconds =
          bestCpuSeconds(repeat, [&] { timeTraceRays(gpu.device, probe, count, gpu::kProbeClosestBare, 1); });
      r.embreeSeconds = bestCpuSeconds(repeat, [&] { embreeTraceClosest(embree, rays); });
      results.push_back(r);
    }
    destroyRayProbe(gpu.device, probe);
    destroyEmbreeTracer(embree);
    destroyGpuScene(gpu.device, gpuScene);
  }
  if (results.empty()) throw Error("raylab bench order: --scene " + only + " is not one of 1k, 100k, 1m, spheres", kExitUsage);

  std::vector<ShadingResult> shading;
  BrdfEvaluator evaluator = createBrdfEvaluator(gpu.device, shadingCount);
  for (bool sorted : {false, true}) {
    const std::vector<gpu::BrdfEvalCase> cases = shadingCases(shadingCount, sorted);
    ShadingResult s;
    s.layout = sorted ? "sorted by model" : "8 models in every 8 lanes";
    s.cases = cases.size();
    evaluateBrdfCases(gpu.device, evaluator, cases);  // compiles the kernel
    s.seconds = 1e30;
    for (std::uint32_t i = 0; i < std::max(repeat, 5u); ++i) {
      double seconds = 0.0;
      evaluateBrdfCases(gpu.device, evaluator, cases, &seconds);
      s.seconds = std::min(s.seconds, seconds);
    }
    shading.push_back(s);
  }
  destroyBrdfEvaluator(gpu.device, evaluator);

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (json) {
    nlohmann::ordered_json report = {{"benchmark", "order"}, {"device", gpu.device.report.name},
                                     {"driver", gpu.device.report.driver}, {"embree", embreeVersion()},
                                     {"cores", cores}, {"size", size}, {"clock", "cpu"}};
    report["bounce"] = nlohmann::ordered_json::array();
    for (const OrderResult& r : results) {
      report["bounce"].push_back({{"scene", r.scene}, {"order", rayOrderName(r.order)}, {"rays", r.rays},
                                  {"raylab_mrays", mrays(r.rays, r.raylabSeconds)},
                                  {"raylab_bare_mrays", mrays(r.rays, r.raylabBareSeconds)},
                                  {"embree_1_mrays", mrays(r.rays, r.embreeSeconds)}});
    }
    report["shading"] = nlohmann::ordered_json::array();
    for (const ShadingResult& s : shading) {
      report["shading"].push_back({{"layout", s.layout}, {"cases", s.cases}, {"seconds", s.seconds}});
    }
    std::printf("%s\n", report.dump().c_str());
    return kExitOk;
  }
  std::printf("device: %s (%s); Embree %s; %u cores; bounce rays of %ux%u primary hits; rates per CPU second\n\n",
              gpu.device.report.name.c_str(), gpu.device.report.driver.c_str(), embreeVersion().c_str(), cores, size,
              size);
  std::printf("%-22s %-14s %9s %10s %10s %10s %9s %12s\n", "scene", "order", "rays", "raylab", "bare", "Embree 1t",
              "raylab /", "vs generated");
  std::printf("%-22s %-14s %9s %10s %10s %10s %9s %12s\n", "", "", "", "Mrays/s", "Mrays/s", "Mrays/s", "Embree", "(raylab)");
  double generated = 0.0;
  for (const OrderResult& r : results) {
    if (r.order == RayOrder::kGenerated) generated = r.raylabSeconds;
    std::printf("%-22s %-14s %9zu %10.2f %10.2f %10.2f %9.2f %11.2fx\n", r.scene.c_str(),
                std::string(rayOrderName(r.order)).c_str(), r.rays, mrays(r.rays, r.raylabSeconds),
                mrays(r.rays, r.raylabBareSeconds), mrays(r.rays, r.embreeSeconds), r.embreeSeconds / r.raylabSeconds,
                generated / r.raylabSeconds);
  }
  std::printf("\nBRDF evaluation on the device (wall clock of the dispatch, best of %u):\n", std::max(repeat, 5u));
  for (const ShadingResult& s : shading) {
    std::printf("  %-26s %8zu cases %9.2f ms %8.1f Mevals/s\n", s.layout.c_str(), s.cases, s.seconds * 1e3,
                s.cases / s.seconds / 1e6);
  }
  std::printf("  mixed / sorted: %.2fx the time\n", shading[0].seconds / shading[1].seconds);
  return kExitOk;
}

}  // namespace

void addBenchOrderCommand(CLI::App& bench) {
  auto o = std::make_shared<OrderOptions>();
  CLI::App* command = addCommand(
      bench, "order",
      "what ray and shading coherence is worth: the same bounce rays in several orders\n"
      "Measures what ray and shading coherence is worth on the device: one diffuse bounce from each of SIZE x "
      "SIZE primary hits of the fixed scenes of `bench rays`, traced by raylab's probe (ray queries) and by Embree "
      "3 (one thread, single rays) in six orders: as generated (pixel order), shuffled, by direction octant, by "
      "octant then a Morton code of the origin, by that Morton code then octant, and every 8th ray 8 times (the "
      "bound of any reordering); rates per CPU second of the process, best of --repeat. Then the BRDF library on "
      "the device with 8 models mixed in every group of 8 lanes against sorted by model.",
      [o] { return benchOrder(*o); });
  addCount(command, "--size", o->size, "primary rays per image side", 16, 4096);
  addCount(command, "--repeat", o->repeat, "timed runs per measurement (best kept)", 1, 100);
  addChoice(command, "--scene", o->only, {"1k", "100k", "1m", "spheres"}, "only this scene");
  addCount(command, "--shading-cases", o->shadingCount, "BRDF evaluations of the shading measurement", 1024, 1u << 22);
  addFlag(command, "--json", o->json, "print one JSON object instead of the tables");
  addDeviceOption(command, o->device);
}

}  // namespace raylab
