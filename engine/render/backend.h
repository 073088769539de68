// raylab's two backends: the same GLSL programs run as compute shaders with ray queries (VK_KHR_ray_query) or as
// the stages of a ray-tracing pipeline with a shader binding table (VK_KHR_ray_tracing_pipeline).
#pragma once

#include <string>

#include "vk/device.h"

namespace raylab {

enum class Backend { kQuery, kPipeline };
enum class BackendChoice { kAuto, kQuery, kPipeline };

// The backend a command runs on `device`: `auto` takes ray queries where the device has them and the pipeline
// otherwise. Throws Error(kExitNoDevice) naming what the device lacks when the requested one is not there.
Backend chooseBackend(const Device& device, BackendChoice choice);

// "query" or "pipeline" (render/render_choices.h parses the option).
const char* backendName(Backend backend);

}  // namespace raylab
