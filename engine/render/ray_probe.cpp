#include "render/ray_probe.h"

#include <algorithm>
#include <string>

#include "shared/bindings.h"
#include "util/error.h"
#include "util/timer.h"
#include "vk/commands.h"

namespace raylab {

namespace {

// The probe once per backend: trace_rays.comp, or its raygen with the probe's closest-hit, the alpha test's
// any-hit and miss programs (the hit goes back to the raygen) and the shadow rays' miss program.
const TracePrograms kProbePrograms{
    "trace_rays.comp", gpu::kProbeWorkgroupSize, 1,
    RayTracingProgram{"trace_rays.rgen",
                      {"probe.rmiss", "shadow.rmiss"},
                      {{"probe.rchit", "", "alpha.rahit"}, {"probe.rchit", "sphere.rint"}},
                      1}};

void recordProbe(VkCommandBuffer cmd, const RayProbe& probe, std::uint32_t rayCount, std::uint32_t mode) {
  const gpu::ProbeParams params{rayCount, mode};
  recordTrace(cmd, probe.kernel, &params, rayCount, 1);
  computeBarrier(cmd);
}

}  // namespace

RayProbe createRayProbe(const Device& device, const GpuScene& gpuScene, std::uint32_t capacity, Backend backend) {
  RayProbe probe;
  probe.capacity = capacity;
  std::vector<DescriptorBinding> bindings = sceneBindings();
  bindings.push_back({gpu::kBindingProbeRays, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  bindings.push_back({gpu::kBindingProbeHits, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  probe.kernel = createTraceKernel(device, backend, kProbePrograms, bindings, sizeof(gpu::ProbeParams), gpuScene);
  try {
    replaceTracePipeline(device, probe.kernel, acquireTracePipeline(device, probe.kernel, nullptr));
  } catch (...) {
    destroyTraceKernel(device, probe.kernel);
    throw;
  }
  probe.rays = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::ProbeRay),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kDevice,
                            "probe rays");
  probe.hits = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::ProbeHit),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kDevice,
                            "probe hits");
  writeSceneDescriptors(device, probe.kernel.descriptors.set, gpuScene);
  probe.sceneRecord = gpuScene.sceneRecord;
  probe.scenePrimitive = gpuScene.scenePrimitive;
  writeStorageBuffer(device, probe.kernel.descriptors.set, gpu::kBindingProbeRays, probe.rays.handle);
  writeStorageBuffer(device, probe.kernel.descriptors.set, gpu::kBindingProbeHits, probe.hits.handle);
  return probe;
}

void destroyRayProbe(const Device& device, RayProbe& probe) {
  destroyBuffer(device, probe.hits);
  destroyBuffer(device, probe.rays);
  destroyTraceKernel(device, probe.kernel);
  probe = {};
}

std::vector<gpu::ProbeHit> traceRays(const Device& device, RayProbe& probe, std::span<const gpu::ProbeRay> rays,
                                     std::uint32_t mode) {
  if (rays.size() > probe.capacity) {
    throw Error("traceRays: " + std::to_string(rays.size()) + " rays exceed the probe's capacity of " +
                std::to_string(probe.capacity));
  }
  const auto count = static_cast<std::uint32_t>(rays.size());
  uploadBuffer(device, probe.rays, rays.data(), rays.size_bytes());
  submitAndWait(device, [&](VkCommandBuffer cmd) { recordProbe(cmd, probe, count, mode); });
  std::vector<gpu::ProbeHit> hits(count);
  downloadBuffer(device, probe.hits, hits.data(), hits.size() * sizeof(gpu::ProbeHit));
  // The device's ids are positions in the upload's spatial order; report the scene's.
  for (gpu::ProbeHit& hit : hits) {
    if (hit.instance >= probe.sceneRecord.size()) continue;
    const std::vector<std::uint32_t>& order = *probe.scenePrimitive[hit.instance];
    if (hit.primitive < order.size()) hit.primitive = order[hit.primitive];
    hit.instance = probe.sceneRecord[hit.instance];
  }
  return hits;
}

double timeTraceRays(const Device& device, RayProbe& probe, std::uint32_t rayCount, std::uint32_t mode,
                     std::uint32_t repetitions) {
  const Stopwatch clock;
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    for (std::uint32_t i = 0; i < repetitions; ++i) recordProbe(cmd, probe, rayCount, mode);
  });
  return clock.seconds() / std::max<std::uint32_t>(1, repetitions);
}

}  // namespace raylab
