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

}  // namespace raylab
