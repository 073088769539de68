// Ray-tracing pipelines (VK_KHR_ray_tracing_pipeline) from embedded SPIR-V, and their shader binding tables:
// one raygen record, the miss records in order, and hit-group records that carry data after their handle
// (OptiX's SBT records). Thin free functions over plain structs, like the compute side in vk/pipeline.h.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace raylab {

// The stages of a ray-tracing pipeline, by embedded kernel name (shaders/<name>). Every stage gets the same
// specialization constants.
struct RayTracingProgram {
  struct HitGroup {
    std::string_view closestHit;
    std::string_view intersection;  // empty for triangles; procedural hit groups have one
    std::string_view anyHit = {};   // empty: none (opaque geometry never runs one anyway)
  };
  std::string_view raygen;
  std::vector<std::string_view> misses;    // miss index i is misses[i]
  std::vector<HitGroup> hitGroups;         // hit group i, the group a hit record names
  std::uint32_t maxRecursionDepth = 1;     // 1: the raygen traces; 2: closest-hit programs trace too
};

// Every stage a ray-tracing pipeline may hold: for descriptor-set and push-constant stage masks.
inline constexpr VkShaderStageFlags kRayTracingStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
    VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR;

// Throws Error when a stage is not embedded or the depth exceeds the device's maxRayRecursionDepth.
VkPipeline acquireRayTracingPipeline(const Device& device, VkPipelineLayout layout, const RayTracingProgram& program,
                                    SpecializationConstants* constants, const char* name);

// One hit-group record: which hit group, and the data that follows its handle.
struct HitRecord {
  std::uint32_t group = 0;
  std::vector<std::uint8_t> data;  // at most the table's dataBytes
};

struct ShaderBindingTable {
  Buffer buffer;
  VkStridedDeviceAddressRegionKHR raygen{};
  VkStridedDeviceAddressRegionKHR miss{};
  VkStridedDeviceAddressRegionKHR hit{};
  VkStridedDeviceAddressRegionKHR callable{};
};

// The table of `pipeline` (built from `program`): its raygen, its misses, and `hits` in order, each record
// `dataBytes` of data after the handle. Record i is what a TLAS instance with SBT record offset i hits.
ShaderBindingTable createShaderBindingTable(const Device& device, VkPipeline pipeline, const RayTracingProgram& program,
                                            std::span<const HitRecord> hits, std::uint32_t dataBytes,
                                            const char* name);
void destroyShaderBindingTable(const Device& device, ShaderBindingTable& table);

}  // namespace raylab
