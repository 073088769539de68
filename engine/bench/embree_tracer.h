// Embree 3 as the CPU baseline of `raylab bench rays`: the same scene (meshes with their instance transforms
// baked in, spheres as Embree's exact sphere points) traced with single-ray queries. A measuring stick and a
// correctness cross-check for the Vulkan kernel, not a second renderer.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shared/frame.h"

namespace raylab {

struct EmbreeScene;  // opaque: keeps Embree's headers out of the engine's interface

struct EmbreeTracer {
  EmbreeScene* scene = nullptr;
  double buildSeconds = 0.0;
  unsigned threads = 1;
};

EmbreeTracer createEmbreeTracer(const Scene& scene, unsigned threads);
void destroyEmbreeTracer(EmbreeTracer& tracer);

// Closest hits in raylab's ProbeHit form (t, a miss as kProbeMiss; position and normal filled).
std::vector<gpu::ProbeHit> embreeTraceClosest(const EmbreeTracer& tracer, std::span<const gpu::ProbeRay> rays);
// Occlusion: 1 when something lies on the ray in [tMin, tMax].
std::vector<std::uint8_t> embreeTraceOcclusion(const EmbreeTracer& tracer, std::span<const gpu::ProbeRay> rays);

std::string embreeVersion();

}  // namespace raylab
