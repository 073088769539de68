// Traces caller-given rays with the renderer's own traversal (trace_rays.comp, or trace_rays.rgen through the
// ray-tracing pipeline) and returns each closest hit.
// Tests compare the hits with analytic geometry; `raylab bench` times them and cross-checks with Embree.
#pragma once

#include <memory>

#include <span>
#include <vector>

#include "render/gpu_scene.h"
#include "shared/frame.h"
#include "vk/device.h"
#include "render/trace_kernel.h"

namespace raylab {

struct RayProbe {
  TraceKernel kernel;
  std::vector<std::uint32_t> sceneRecord;  // the GpuScene's, to report the scene's ids
  std::vector<std::shared_ptr<const std::vector<std::uint32_t>>> scenePrimitive;
  Buffer rays;
  Buffer hits;
  std::uint32_t capacity = 0;  // rays the buffers hold
};

RayProbe createRayProbe(const Device& device, const GpuScene& gpuScene, std::uint32_t capacity,
                        Backend backend = Backend::kQuery);
void destroyRayProbe(const Device& device, RayProbe& probe);

// Uploads the rays (at most `capacity`), traces them in one dispatch and downloads the hits. `mode`:
// gpu::kProbeClosest, kProbeOcclusion or kProbeClosestBare.
std::vector<gpu::ProbeHit> traceRays(const Device& device, RayProbe& probe, std::span<const gpu::ProbeRay> rays,
                                     std::uint32_t mode = gpu::kProbeClosest);

// Times `repetitions` dispatches over the rays of the last traceRays call; returns seconds per dispatch.
double timeTraceRays(const Device& device, RayProbe& probe, std::uint32_t rayCount, std::uint32_t mode,
                     std::uint32_t repetitions);

}  // namespace raylab
