// The BRDF library's precomputed tables on the device: the one read-only buffer (binding kBindingBrdfTables,
// layout shared/brdf_tables.h) that every kernel evaluating BRDFs binds beside its own buffers: the build-time
// tables, then one block per measured file the materials use.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shared/scene_records.h"
#include "vk/resources.h"

namespace raylab {

// The buffer's floats before any measured block, from the build-time tables (generated/ggx_albedo.h).
std::vector<float> brdfTableValues();

// Material records as the device sees them, and the measured files they use: each file once, in order of first
// use, its block's number replacing the file's id (measured/measured_library.h) in every `file` parameter.
struct DeviceMaterials {
  std::vector<gpu::MaterialRecord> records;
  std::vector<std::uint32_t> measuredFiles;
};
// Throws Error naming the material (`names[i]`, or its index) when a file parameter has no file.
DeviceMaterials deviceMaterials(std::span<const gpu::MaterialRecord> records, std::span<const std::string> names = {});

// A device-local buffer holding brdfTableValues() and the blocks of `measuredFiles`; the caller destroys it with
// destroyBuffer. Throws Error when the blocks exceed the device's maxStorageBufferRange.
Buffer createBrdfTables(const Device& device, std::span<const std::uint32_t> measuredFiles = {});

// Rebuilds `tables` when `wanted` differs from `current` (the files it holds), the new buffer made before the old
// goes so that a refused set (too large) leaves it as it was. Returns true when it replaced the buffer: every
// descriptor set holding the old one must be written again.
bool updateBrdfTables(const Device& device, Buffer& tables, std::vector<std::uint32_t>& current,
                      std::span<const std::uint32_t> wanted);

}  // namespace raylab
