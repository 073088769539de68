// `raylab bench rays`: the same rays (primary, shadow, one diffuse bounce) of fixed scenes traced by raylab's
// kernel on the Vulkan device and by Embree 3 on the CPU, in one run: Mrays/s, their ratio, build times, and a
// hit/miss and distance cross-check.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_line/cli.h"
#include "bench/bench_scenes.h"
#include "bench/embree_tracer.h"
#include "bench/ray_sets.h"
#include "bench_commands.h"
#include "session/gpu_session.h"
#include "render/ray_probe.h"
#include "render/renderer.h"
#include "render/gpu_scene.h"
#include "util/error.h"
#include "util/progress.h"
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
// The primitive order of the run (--shuffle, --submitted-order), for the JSON report.
bool gShuffled = false;
bool gSubmittedOrder = false;

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

// raylab's times on one backend.
struct BackendTimes {
  Backend backend = Backend::kQuery;
  double seconds = 0.0;
  double bareSeconds = 0.0;  // closest-hit sets only: traversal without surface reconstruction
};

struct SetResult {
  std::string scene;
  std::string set;
  std::size_t rays = 0;
  std::vector<BackendTimes> raylab;  // per backend compared, in order
  double embreeOneSeconds = 0.0;
  double embreeAllSeconds = 0.0;
  Agreement agreement;               // the first backend against Embree
  std::size_t backendsDiffer = 0;    // rays whose hit records differ between the backends (bit for bit)
};

double mrays(std::size_t rays, double seconds) { return seconds > 0.0 ? rays / seconds / 1e6 : 0.0; }

// The whole render kernel (one sample, pixel centres: the same primary rays) against bare queries of its ray
// mix: what shading, payload, accumulation and divergence cost on top of traversal.
struct KernelResult {
  std::string scene;
  Backend backend = Backend::kQuery;
  double renderMrays = 0.0;  // rays the render kernel traced per second of its dispatch
  double bareMrays = 0.0;    // the same mix of primary and shadow rays as bare queries
};

KernelResult timeRenderKernel(const Device& device, const GpuScene& gpuScene, const Scene& scene, std::uint32_t size,
                              std::uint32_t repeat, const BackendTimes& primary, std::size_t primaryRays,
                              const BackendTimes& shadow, std::size_t shadowRays) {
  RenderSettings settings;
  settings.width = size;
  settings.height = size;
  settings.jitter = false;
  settings.backend = primary.backend;
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, 1);  // the driver compiles the kernel here
  const RayCounts before = renderer.rays;
  const double seconds = bestOf(repeat, [&] { renderSamples(device, renderer, 1); });
  const double primaryPerSample = double(renderer.rays.primary - before.primary) / repeat;
  const double shadowPerSample = double(renderer.rays.shadow - before.shadow) / repeat;
  destroyRenderer(device, renderer);

  KernelResult result;
  result.scene = scene.name;
  result.backend = primary.backend;
  result.renderMrays = (primaryPerSample + shadowPerSample) / seconds / 1e6;
  const double bareSeconds = primaryPerSample * primary.bareSeconds / primaryRays +
                             shadowPerSample * shadow.seconds / shadowRays;
  result.bareMrays = (primaryPerSample + shadowPerSample) / bareSeconds / 1e6;
  return result;
}

// Ray records of two backends that differ bit for bit.
std::size_t differingHits(std::span<const gpu::ProbeHit> a, std::span<const gpu::ProbeHit> b) {
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += std::memcmp(&a[i], &b[i], sizeof(gpu::ProbeHit)) != 0;
  return differ;
}

struct BuildTimes {
  std::string scene;
  double raylab = 0.0;
  double embree = 0.0;
};

// The first trace of each backend's probe: the driver compiles it there.
struct FirstTrace {
  std::string scene;
  Backend backend = Backend::kQuery;
  double seconds = 0.0;
};

void printJson(const Device& device, unsigned cores, std::uint32_t size, const std::vector<BuildTimes>& builds,
               const std::vector<FirstTrace>& firsts, const std::vector<SetResult>& results,
               const std::vector<KernelResult>& kernels) {
  using nlohmann::ordered_json;
  ordered_json report = {{"benchmark", "rays"}, {"device", device.report.name}, {"driver", device.report.driver},
                         {"embree", embreeVersion()}, {"cores", cores}, {"size", size},
                         {"clock", gCpuTime ? "cpu" : "wall"}};
  report["builds"] = ordered_json::array();
  for (const BuildTimes& b : builds) report["builds"].push_back({{"scene", b.scene}, {"raylab_s", b.raylab}, {"embree_s", b.embree}});
  report["first_trace"] = ordered_json::array();
  for (const FirstTrace& f : firsts) {
    report["first_trace"].push_back({{"scene", f.scene}, {"backend", backendName(f.backend)}, {"seconds", f.seconds}});
  }
  report["primitive_order"] = {{"shuffled", gShuffled}, {"spatially_sorted", !gSubmittedOrder}};
  report["sets"] = ordered_json::array();
  for (const SetResult& r : results) {
    ordered_json set = {{"scene", r.scene}, {"set", r.set}, {"rays", r.rays}};
    for (const BackendTimes& t : r.raylab) {
      const std::string name = backendName(t.backend);
      set[name + "_mrays"] = mrays(r.rays, t.seconds);
      set[name + "_bare_mrays"] = mrays(r.rays, t.bareSeconds);
    }
    set["embree_1_mrays"] = mrays(r.rays, r.embreeOneSeconds);
    set["embree_all_mrays"] = mrays(r.rays, r.embreeAllSeconds);
    set["mismatched"] = r.agreement.mismatched;
    set["far_apart"] = r.agreement.farApart;
    set["worst_relative_t"] = r.agreement.worstRelativeT;
    set["backends_differ"] = r.backendsDiffer;
    report["sets"].push_back(set);
  }
  report["render_kernel"] = ordered_json::array();
  for (const KernelResult& k : kernels) {
    report["render_kernel"].push_back({{"scene", k.scene}, {"backend", backendName(k.backend)},
                                       {"render_mrays", k.renderMrays}, {"bare_mrays", k.bareMrays}});
  }
  std::printf("%s\n", report.dump().c_str());
}

void printTable(const Device& device, unsigned cores, std::uint32_t size, const std::vector<BuildTimes>& builds,
                const std::vector<FirstTrace>& firsts, const std::vector<SetResult>& results,
                const std::vector<KernelResult>& kernels) {
  std::printf("device: %s (%s); Embree %s; %u cores; %ux%u primary rays; rates per %s second\n",
              device.report.name.c_str(), device.report.driver.c_str(), embreeVersion().c_str(), cores, size, size,
              gCpuTime ? "CPU" : "wall-clock");
  std::printf("\nacceleration structure builds:\n");
  for (const BuildTimes& b : builds) {
    std::printf("  %-22s raylab %8.1f ms   Embree (%u threads) %8.1f ms\n", b.scene.c_str(), b.raylab * 1e3, cores,
                b.embree * 1e3);
  }
  std::printf("\nfirst trace of the probe (the driver compiles it):\n");
  for (const FirstTrace& f : firsts) {
    std::printf("  %-22s %-9s %s\n", f.scene.c_str(), backendName(f.backend), formatSeconds(f.seconds).c_str());
  }
  std::printf("\n%-22s %-8s %9s", "scene", "rays", "count");
  for (const BackendTimes& t : results.front().raylab) std::printf(" %10s %10s", backendName(t.backend), "(bare)");
  std::printf(" %10s %10s %9s %14s %9s\n", "Embree 1t", "Embree all", "raylab /", "hit/miss", "backends");
  std::printf("%-22s %-8s %9s", "", "", "");
  for (std::size_t i = 0; i < results.front().raylab.size(); ++i) std::printf(" %10s %10s", "Mrays/s", "Mrays/s");
  std::printf(" %10s %10s %9s %14s %9s\n", "Mrays/s", "Mrays/s", "Emb. all", "differ, t>1e-3", "differ");
  for (const SetResult& r : results) {
    std::printf("%-22s %-8s %9zu", r.scene.c_str(), r.set.c_str(), r.rays);
    for (const BackendTimes& t : r.raylab) {
      char bare[16] = "-";
      if (t.bareSeconds > 0.0) std::snprintf(bare, sizeof bare, "%.2f", mrays(r.rays, t.bareSeconds));
      std::printf(" %10.2f %10s", mrays(r.rays, t.seconds), bare);
    }
    std::printf(" %10.2f %10.2f %9.2f %8zu, %4zu %9zu\n", mrays(r.rays, r.embreeOneSeconds),
                mrays(r.rays, r.embreeAllSeconds), r.embreeAllSeconds / r.raylab.front().seconds, r.agreement.mismatched,
                r.agreement.farApart, r.backendsDiffer);
  }
  std::printf("\nrender kernel (1 spp, pixel centres) against bare queries of the same primary/shadow mix:\n");
  for (const KernelResult& k : kernels) {
    std::printf("  %-22s %-9s render %6.2f Mrays/s   bare %6.2f Mrays/s   render / bare %5.2fx\n",
                k.scene.c_str(), backendName(k.backend), k.renderMrays, k.bareMrays, k.renderMrays / k.bareMrays);
  }
  // A ratio, not an efficiency: the render traces each pixel's shadow ray right after its primary, on rays that
  // hit nearby nodes, while the bare mix traces all primaries and then all shadow rays; above 1 is normal.
  std::printf("  (render / bare above 1: the kernel's rays are more coherent than the bare mix's)\n");
}

struct RaysOptions {
  std::uint32_t size = 512;
  std::uint32_t repeat = 3;
  std::string only;
  bool cpuTime = false;
  bool shuffle = false;
  bool submittedOrder = false;
  std::string backendChoice = "all";
  bool json = false;
  std::optional<std::uint32_t> device;
};

int benchRays(const RaysOptions& o) {
  const std::uint32_t size = o.size, repeat = o.repeat;
  const std::string& only = o.only;
  const bool json = o.json;
  gCpuTime = o.cpuTime;
  gShuffled = o.shuffle;
  gSubmittedOrder = o.submittedOrder;

  GpuSession gpu(o.device, json);
  const std::vector<Backend> backends = backendsToCompare(gpu.device, o.backendChoice);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<SetResult> results;
  std::vector<BuildTimes> builds;
  std::vector<FirstTrace> firsts;
  std::vector<KernelResult> kernels;

  // Which order the trees are built from, said before the minutes it may take: shuffled triangles without the
  // spatial sort make the worst trees (about 4 minutes on 2 cores for every scene).
  if (!json) {
    std::printf("primitive order: %s%s\n", o.shuffle ? "shuffled" : "as generated",
                o.submittedOrder ? ", trees built in that order (no spatial sort)" : ", spatially sorted before the build");
    if (o.shuffle && o.submittedOrder) {
      std::fprintf(stderr, "raylab bench rays: --shuffle with --submitted-order builds the worst trees: expect minutes "
                           "(about 4 on 2 cores); --scene picks one scene\n");
    }
    std::fflush(stdout);
  }
  for (const BenchSceneInfo& info : allBenchScenes()) {
    if (!only.empty() && only != info.key) continue;
    Scene scene = makeBenchScene(info.kind);
    if (o.shuffle) shuffleTriangles(scene, 12345);
    GpuScene gpuScene = uploadScene(gpu.device, scene, {.spatialOrder = !o.submittedOrder});
    EmbreeTracer embreeOne = createEmbreeTracer(scene, 1);
    EmbreeTracer embreeAll = createEmbreeTracer(scene, cores);
    builds.push_back({scene.name, gpuScene.accelerationBuildSeconds, embreeAll.buildSeconds});

    const std::vector<gpu::ProbeRay> primary = primaryRays(scene, size, size);
    std::vector<RayProbe> probes;
    std::vector<gpu::ProbeHit> primaryHits;
    for (Backend backend : backends) {
      probes.push_back(createRayProbe(gpu.device, gpuScene, static_cast<std::uint32_t>(primary.size()), backend));
      const Stopwatch first;
      primaryHits = traceRays(gpu.device, probes.back(), primary);  // also the warm-up
      firsts.push_back({scene.name, backend, first.seconds()});
    }
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
      std::vector<gpu::ProbeHit> raylabHits;
      for (std::size_t b = 0; b < backends.size(); ++b) {
        RayProbe& probe = probes[b];
        BackendTimes times;
        times.backend = backends[b];
        const std::vector<gpu::ProbeHit> hits = traceRays(gpu.device, probe, *set.rays, mode);
        if (b == 0) raylabHits = hits;
        else r.backendsDiffer += differingHits(raylabHits, hits);
        times.seconds = bestOf(repeat, [&] { timeTraceRays(gpu.device, probe, count, mode, 1); });
        if (!set.occlusion) {
          traceRays(gpu.device, probe, *set.rays, gpu::kProbeClosestBare);
          times.bareSeconds = bestOf(repeat, [&] { timeTraceRays(gpu.device, probe, count, gpu::kProbeClosestBare, 1); });
        }
        r.raylab.push_back(times);
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
    const SetResult& primaryResult = results[results.size() - 3];
    const SetResult& shadowResult = results[results.size() - 2];
    for (std::size_t b = 0; b < backends.size(); ++b) {
      kernels.push_back(timeRenderKernel(gpu.device, gpuScene, scene, size, repeat, primaryResult.raylab[b],
                                         primaryResult.rays, shadowResult.raylab[b], shadowResult.rays));
    }
    for (RayProbe& probe : probes) destroyRayProbe(gpu.device, probe);
    destroyEmbreeTracer(embreeAll);
    destroyEmbreeTracer(embreeOne);
    destroyGpuScene(gpu.device, gpuScene);
  }
  if (results.empty()) throw Error("raylab bench rays: --scene " + only + " is not one of 1k, 100k, 1m, spheres", kExitUsage);

  if (json) {
    printJson(gpu.device, cores, size, builds, firsts, results, kernels);
  } else {
    printTable(gpu.device, cores, size, builds, firsts, results, kernels);
  }
  return kExitOk;
}

}  // namespace

void addBenchRaysCommand(CLI::App& bench) {
  auto o = std::make_shared<RaysOptions>();
  CLI::App* command = addCommand(
      bench, "rays",
      "raylab's two backends against Embree 3 on the same rays of fixed scenes\n"
      "Traces the same rays (primary rays through SIZE x SIZE pixel centres, shadow rays from every hit to the "
      "light, one diffuse bounce per hit) of four fixed scenes (64 spheres tessellated to 1k, 100k and 1M "
      "triangles, and as analytic spheres) with raylab's kernel on each backend (ray queries, ray-tracing "
      "pipeline) and with Embree 3 (one thread, and as many threads as cores), and cross-checks hits and "
      "distances. Times are the best of --repeat runs, after a warm-up that compiles the kernel (its time is "
      "printed as the first trace).",
      [o] { return benchRays(*o); });
  addCount(command, "--size", o->size, "primary rays per image side", 16, 4096);
  addCount(command, "--repeat", o->repeat, "timed runs per measurement (best kept)", 1, 100);
  addChoice(command, "--scene", o->only, {"1k", "100k", "1m", "spheres"}, "only this scene");
  addFlag(command, "--cpu-time", o->cpuTime,
          "rate rays per CPU-second of the whole process instead of per wall-clock second: steadier on a shared "
          "machine, and fair between tracers using different thread counts");
  addFlag(command, "--shuffle", o->shuffle,
          "the meshes' triangles in a random order (as a file from an exporter or optimiser may hold them)");
  addFlag(command, "--submitted-order", o->submittedOrder,
          "build the trees from the primitives in the scene's own order, without raylab's spatial sort (to measure "
          "what the sort is worth)");
  addFlag(command, "--json", o->json, "print one JSON object instead of the table");
  addBenchBackendOption(command, o->backendChoice);
  addDeviceOption(command, o->device);
}

}  // namespace raylab
