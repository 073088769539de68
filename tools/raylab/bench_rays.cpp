// `raylab bench rays`: the same rays (primary, shadow, one diffuse bounce) of fixed scenes traced by raylab's
// kernel on the Vulkan device and by Embree 3 on the CPU, in one run: Mrays/s, their ratio, build times, and a
// hit/miss and distance cross-check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "args.h"
#include "bench/bench_scenes.h"
#include "bench/embree_tracer.h"
#include "bench/ray_sets.h"
#include "bench_commands.h"
#include "gpu_session.h"
#include "render/ray_probe.h"
#include "render/renderer.h"
#include "scene/gpu_scene.h"
#include "util/error.h"
#include "util/timer.h"

namespace raylab {

namespace {

struct Agreement {
  std::size_t rays = 0;
  std::size_t mismatched = 0;    // one hit, the other missed (or occlusion disagrees)
  double worstRelativeT = 0.0;   // over rays both hit
  std::size_t farApart = 0;      // both hit, distances differ by more than 1e-3 relative: different surfaces
};

Agreement compareClosest(std::span<const gpu::ProbeHit> a, std::span<const gpu::ProbeHit> b) {
  Agreement agreement;
  agreement.rays = a.size();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bool hitA = a[i].instance != gpu::kProbeMiss, hitB = b[i].instance != gpu::kProbeMiss;
    if (hitA != hitB) {
      ++agreement.mismatched;
    } else if (hitA) {
      const double relative = std::abs(double(a[i].t) - b[i].t) / std::max(1e-6, double(b[i].t));
      agreement.worstRelativeT = std::max(agreement.worstRelativeT, relative);
      if (relative > 1e-3) ++agreement.farApart;
    }
  }
  return agreement;
}

Agreement compareOcclusion(std::span<const gpu::ProbeHit> a, std::span<const std::uint8_t> b) {
  Agreement agreement;
  agreement.rays = a.size();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if ((a[i].instance != gpu::kProbeMiss) != (b[i] != 0)) ++agreement.mismatched;
  }
  return agreement;
}

// What the benchmark times: wall-clock seconds, or (with --cpu-time) CPU seconds of the whole process.
bool gCpuTime = false;

// Best of `repeat` runs of `work`, in seconds: the least disturbed by other processes.
template <class Work>
double bestOf(std::uint32_t repeat, const Work& work) {
  double best = 1e30;
  for (std::uint32_t i = 0; i < repeat; ++i) {
    const Stopwatch wall;
    const CpuStopwatch cpu;
    work();
    best = std::min(best, gCpuTime ? cpu.seconds() : wall.seconds());
  }
  return best;
}

struct SetResult {
  std::string scene;
  std::string set;
  std::size_t rays = 0;
  double raylabSeconds = 0.0;
  double raylabBareSeconds = 0.0;  // closest-hit sets only: traversal without surface reconstruction
  double embreeOneSeconds = 0.0;
  double embreeAllSeconds = 0.0;
  Agreement agreement;
};

double mrays(std::size_t rays, double seconds) { return seconds > 0.0 ? rays / seconds / 1e6 : 0.0; }

// The whole render kernel (one sample, pixel centres: the same primary rays) against bare queries of its ray
// mix: what shading, payload, accumulation and divergence cost on top of traversal.
struct KernelResult {
  std::string scene;
  double renderMrays = 0.0;  // rays the render kernel traced per second of its dispatch
  double bareMrays = 0.0;    // the same mix of primary and shadow rays as bare queries
};

KernelResult timeRenderKernel(const Device& device, const GpuScene& gpuScene, const Scene& scene, std::uint32_t size,
                              std::uint32_t repeat, const SetResult& primary, const SetResult& shadow) {
  RenderSettings settings;
  settings.width = size;
  settings.height = size;
  settings.jitter = false;
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, 1);  // the driver compiles the kernel here
  const RayCounts before = renderer.rays;
  const double seconds = bestOf(repeat, [&] { renderSamples(device, renderer, 1); });
  const double primaryPerSample = double(renderer.rays.primary - before.primary) / repeat;
  const double shadowPerSample = double(renderer.rays.shadow - before.shadow) / repeat;
  destroyRenderer(device, renderer);

  KernelResult result;
  result.scene = scene.name;
  result.renderMrays = (primaryPerSample + shadowPerSample) / seconds / 1e6;
  const double bareSeconds = primaryPerSample * primary.raylabBareSeconds / primary.rays +
                             shadowPerSample * shadow.raylabSeconds / shadow.rays;
  result.bareMrays = (primaryPerSample + shadowPerSample) / bareSeconds / 1e6;
  return result;
}

}  // namespace

int benchRays(int argc, char** argv) {
  std::uint32_t size = 512, repeat = 3;
  std::string only;
  bool json = false;
  std::optional<std::uint32_t> deviceIndex;
  ArgParser args("raylab bench rays", "[options]",
                 "Traces the same rays (primary rays through SIZE x SIZE pixel centres, shadow rays from every hit\n"
                 "to the light, one diffuse bounce per hit) of four fixed scenes (64 spheres tessellated to 1k,\n"
                 "100k and 1M triangles, and as analytic spheres) with raylab's kernel and with Embree 3 (one\n"
                 "thread, and as many threads as cores), and cross-checks hits and distances. Times are the best\n"
                 "of --repeat runs, after a warm-up that compiles the kernel.");
  args.option("--size", &size, "primary rays per image side", 16, 4096);
  args.option("--repeat", &repeat, "timed runs per measurement (best kept)", 1, 100);
  args.option("--scene", &only, "KEY", "only this scene: 1k, 100k, 1m or spheres");
  args.flag("--cpu-time", &gCpuTime,
            "rate rays per CPU-second of the whole process instead of per wall-clock second: steadier on a\n"
            "                           shared machine, and fair between tracers using different thread counts");
  args.flag("--json", &json, "print one JSON object instead of the table");
  args.option("--device", &deviceIndex, "Vulkan device index from `raylab devices`");
  if (!args.parse(argc, argv)) return kExitOk;

  GpuSession gpu(deviceIndex, json);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<SetResult> results;
  struct BuildTimes {
    std::string scene;
    double raylab, embree;
  };
  std::vector<BuildTimes> builds;
  std::vector<KernelResult> kernels;

  for (const BenchSceneInfo& info : allBenchScenes()) {
    if (!only.empty() && only != info.key) continue;
    const Scene scene = makeBenchScene(info.kind);
    GpuScene gpuScene = uploadScene(gpu.device, scene);
    EmbreeTracer embreeOne = createEmbreeTracer(scene, 1);
    EmbreeTracer embreeAll = createEmbreeTracer(scene, cores);
    builds.push_back({scene.name, gpuScene.accelerationBuildSeconds, embreeAll.buildSeconds});

    const std::vector<gpu::ProbeRay> primary = primaryRays(scene, size, size);
    RayProbe probe = createRayProbe(gpu.device, gpuScene, static_cast<std::uint32_t>(primary.size()));
    const std::vector<gpu::ProbeHit> primaryHits = traceRays(gpu.device, probe, primary);  // also the warm-up
    const std::vector<gpu::ProbeRay> shadow = shadowRays(primaryHits, primary, scene.lights[0].record.position);
    const std::vector<gpu::ProbeRay> bounce = bounceRays(primaryHits, primary);

    struct Set {
      const char* name;
      const std::vector<gpu::ProbeRay>* rays;
      bool occlusion;
    };
    for (const Set& set : {Set{"primary", &primary, false}, Set{"shadow", &shadow, true}, Set{"bounce", &bounce, false}}) {
      SetResult r;
      r.scene = scene.name;
      r.set = set.name;
      r.rays = set.rays->size();
      const auto count = static_cast<std::uint32_t>(r.rays);
      const std::uint32_t mode = set.occlusion ? gpu::kProbeOcclusion : gpu::kProbeClosest;
      const std::vector<gpu::ProbeHit> raylabHits = traceRays(gpu.device, probe, *set.rays, mode);
      r.raylabSeconds = bestOf(repeat, [&] { timeTraceRays(gpu.device, probe, count, mode, 1); });
      if (!set.occlusion) {
        traceRays(gpu.device, probe, *set.rays, gpu::kProbeClosestBare);
        r.raylabBareSeconds = bestOf(repeat, [&] { timeTraceRays(gpu.device, probe, count, gpu::kProbeClosestBare, 1); });
      }
      if (set.occlusion) {
        const std::vector<std::uint8_t> occluded = embreeTraceOcclusion(embreeAll, *set.rays);
        r.agreement = compareOcclusion(raylabHits, occluded);
        r.embreeOneSeconds = bestOf(repeat, [&] { embreeTraceOcclusion(embreeOne, *set.rays); });
        r.embreeAllSeconds = bestOf(repeat, [&] { embreeTraceOcclusion(embreeAll, *set.rays); });
      } else {
        const std::vector<gpu::ProbeHit> embreeHits = embreeTraceClosest(embreeAll, *set.rays);
        r.agreement = compareClosest(raylabHits, embreeHits);
        r.embreeOneSeconds = bestOf(repeat, [&] { embreeTraceClosest(embreeOne, *set.rays); });
        r.embreeAllSeconds = bestOf(repeat, [&] { embreeTraceClosest(embreeAll, *set.rays); });
      }
      results.push_back(r);
    }
    kernels.push_back(timeRenderKernel(gpu.device, gpuScene, scene, size, repeat, results[results.size() - 3],
                                       results[results.size() - 2]));
    destroyRayProbe(gpu.device, probe);
    destroyEmbreeTracer(embreeAll);
    destroyEmbreeTracer(embreeOne);
    destroyGpuScene(gpu.device, gpuScene);
  }
  if (results.empty()) throw Error("raylab bench rays: --scene " + only + " is not one of 1k, 100k, 1m, spheres", kExitUsage);

  if (json) {
    std::printf("{\"benchmark\": \"rays\", \"device\": \"%s\", \"driver\": \"%s\", \"embree\": \"%s\", \"cores\": %u, "
                "\"size\": %u, \"clock\": \"%s\", \"builds\": [",
                gpu.device.report.name.c_str(), gpu.device.report.driver.c_str(), embreeVersion().c_str(), cores, size,
                gCpuTime ? "cpu" : "wall");
    for (std::size_t i = 0; i < builds.size(); ++i) {
      std::printf("%s{\"scene\": \"%s\", \"raylab_s\": %.6f, \"embree_s\": %.6f}", i ? ", " : "", builds[i].scene.c_str(),
                  builds[i].raylab, builds[i].embree);
    }
    std::printf("], \"sets\": [");
    for (std::size_t i = 0; i < results.size(); ++i) {
      const SetResult& r = results[i];
      std::printf("%s{\"scene\": \"%s\", \"set\": \"%s\", \"rays\": %zu, \"raylab_mrays\": %.4f, "
                  "\"raylab_bare_mrays\": %.4f, \"embree_1_mrays\": %.4f, \"embree_all_mrays\": %.4f, "
                  "\"mismatched\": %zu, \"far_apart\": %zu, \"worst_relative_t\": %.3g}",
                  i ? ", " : "", r.scene.c_str(), r.set.c_str(), r.rays, mrays(r.rays, r.raylabSeconds),
                  mrays(r.rays, r.raylabBareSeconds), mrays(r.rays, r.embreeOneSeconds),
                  mrays(r.rays, r.embreeAllSeconds), r.agreement.mismatched, r.agreement.farApart,
                  r.agreement.worstRelativeT);
    }
    std::printf("], \"render_kernel\": [");
    for (std::size_t i = 0; i < kernels.size(); ++i) {
      std::printf("%s{\"scene\": \"%s\", \"render_mrays\": %.4f, \"bare_mrays\": %.4f}", i ? ", " : "",
                  kernels[i].scene.c_str(), kernels[i].renderMrays, kernels[i].bareMrays);
    }
    std::printf("]}\n");
    return kExitOk;
  }

  std::printf("device: %s (%s); Embree %s; %u cores; %ux%u primary rays; rates per %s second\n",
              gpu.device.report.name.c_str(), gpu.device.report.driver.c_str(), embreeVersion().c_str(), cores, size,
              size, gCpuTime ? "CPU" : "wall-clock");
  std::printf("\nacceleration structure builds:\n");
  for (const BuildTimes& b : builds) {
    std::printf("  %-22s raylab %8.1f ms   Embree (%u threads) %8.1f ms\n", b.scene.c_str(), b.raylab * 1e3, cores,
                b.embree * 1e3);
  }
  std::printf("\n%-22s %-8s %9s %10s %10s %10s %10s %9s %10s\n", "scene", "rays", "count", "raylab", "bare query",
              "Embree 1t", "Embree all", "raylab /", "hit/miss");
  std::printf("%-22s %-8s %9s %10s %10s %10s %10s %9s %10s\n", "", "", "", "Mrays/s", "Mrays/s", "Mrays/s", "Mrays/s",
              "Emb. all", "differ, t>1e-3");
  for (const SetResult& r : results) {
    char bare[16] = "-";
    if (r.raylabBareSeconds > 0.0) std::snprintf(bare, sizeof bare, "%.2f", mrays(r.rays, r.raylabBareSeconds));
    std::printf("%-22s %-8s %9zu %10.2f %10s %10.2f %10.2f %9.2f %5zu, %zu\n", r.scene.c_str(), r.set.c_str(), r.rays,
                mrays(r.rays, r.raylabSeconds), bare, mrays(r.rays, r.embreeOneSeconds),
                mrays(r.rays, r.embreeAllSeconds), r.embreeAllSeconds / r.raylabSeconds, r.agreement.mismatched,
                r.agreement.farApart);
  }
  std::printf("\nrender kernel (1 spp, pixel centres) against bare queries of the same primary/shadow mix:\n");
  for (const KernelResult& k : kernels) {
    std::printf("  %-22s render %6.2f Mrays/s   bare %6.2f Mrays/s   kernel efficiency %3.0f%%\n", k.scene.c_str(),
                k.renderMrays, k.bareMrays, 100.0 * k.renderMrays / k.bareMrays);
  }
  return kExitOk;
}

}  // namespace raylab
