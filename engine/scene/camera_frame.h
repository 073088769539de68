// The pinhole camera as the kernels see it (FrameParams: origin, forward, and right and up scaled by the field of
// view), from a scene's Camera. The renderer, the viewer's pivot, the benchmarks' rays and the tests' analytic
// projections all use this one mapping.
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "shared/frame.h"

namespace raylab {

// Camera of FrameParams for an image of width x height; throws Error on a degenerate camera.
void applyCamera(gpu::FrameParams& params, const Camera& camera, std::uint32_t width, std::uint32_t height);

// The unit direction of the primary ray (params.width and height set) through `offset` ([0, 1)^2, 0.5 the centre) of `pixel`: the kernels'
// primaryDirection (shaders/kernel/raygen.glsl).
glm::vec3 primaryDirection(const gpu::FrameParams& params, glm::uvec2 pixel, glm::vec2 offset = glm::vec2(0.5f));

}  // namespace raylab
