// The BRDF library's precomputed tables on the device: the one read-only buffer (binding kBindingBrdfTables,
// layout shared/brdf_tables.h) that every kernel evaluating BRDFs binds beside its own buffers.
#pragma once

#include <vector>

#include "vk/resources.h"

namespace raylab {

// The buffer's floats, from the build-time tables (generated/ggx_albedo.h).
std::vector<float> brdfTableValues();

// A device-local buffer holding brdfTableValues(); the caller destroys it with destroyBuffer.
Buffer createBrdfTables(const Device& device);

}  // namespace raylab
