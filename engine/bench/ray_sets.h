// The rays `raylab bench rays` traces with both raylab and Embree: primary rays through pixel centres,
// shadow rays from every primary hit towards the scene's first light, and one diffuse bounce per hit.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"
#include "shared/frame.h"

namespace raylab {

std::vector<gpu::ProbeRay> primaryRays(const Scene& scene, std::uint32_t width, std::uint32_t height);

// From each primary hit (misses are skipped) towards `lightPosition`, stopping at the light.
std::vector<gpu::ProbeRay> shadowRays(std::span<const gpu::ProbeHit> hits, std::span<const gpu::ProbeRay> rays,
                                      glm::vec3 lightPosition);

// From each primary hit, one cosine-distributed direction about the normal facing the ray (fixed seed).
std::vector<gpu::ProbeRay> bounceRays(std::span<const gpu::ProbeHit> hits, std::span<const gpu::ProbeRay> rays);

// Wächter & Binder's robust origin offset (Ray Tracing Gems ch. 6), as shaders/common/ray_offset.glsl.
glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n);

}  // namespace raylab
