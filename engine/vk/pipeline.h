// Compute pipelines from embedded SPIR-V, specialization constants, and descriptor sets.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "vk/device.h"

namespace raylab {

// The one helper for specialization constants: kernels are specialised per scene with these (STYLE.md).
class SpecializationConstants {
 public:
  SpecializationConstants& set(std::uint32_t id, std::uint32_t value);
  // Valid while this object lives and is not modified.
  const VkSpecializationInfo* info();
  // Each (constant id, value), in the order set.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> values() const;

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<std::uint32_t> values_;
  VkSpecializationInfo info_{};
};

struct DescriptorBinding {
  std::uint32_t binding;
  VkDescriptorType type;
};

// Every binding is visible to `stages` (compute, or the ray-tracing stages of vk/ray_tracing_pipeline.h).
VkDescriptorSetLayout createDescriptorSetLayout(const Device& device, std::span<const DescriptorBinding> bindings,
                                                const char* name, VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);

// A pipeline layout with one descriptor set and `pushConstantBytes` of push constants for `stages`.
VkPipelineLayout createPipelineLayout(const Device& device, VkDescriptorSetLayout setLayout,
                                      std::uint32_t pushConstantBytes, const char* name,
                                      VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);

// A module of the kernel embedded as `kernelName` (shaders/<kernelName>), debug-named after it, specialised on the
// host with `constants` where given (vk/spirv_specialization.h); the caller destroys it once its pipeline exists.
// Throws if it is not embedded.
VkShaderModule createShaderModule(const Device& device, std::string_view kernelName,
                                  const SpecializationConstants* constants = nullptr);

// Builds the kernel embedded as `kernelName` (shaders/<kernelName>). Throws if it is not embedded.
VkPipeline createComputePipeline(const Device& device, VkPipelineLayout layout, std::string_view kernelName,
                                 SpecializationConstants* constants = nullptr);

// A pool and one set for `bindings`; the set lives as long as the pool.
struct DescriptorSet {
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
};
DescriptorSet allocateDescriptorSet(const Device& device, VkDescriptorSetLayout layout,
                                    std::span<const DescriptorBinding> bindings, const char* name);
void destroyDescriptorSet(const Device& device, DescriptorSet& set);

void writeStorageBuffer(const Device& device, VkDescriptorSet set, std::uint32_t binding, VkBuffer buffer);
void writeAccelerationStructure(const Device& device, VkDescriptorSet set, std::uint32_t binding,
                                VkAccelerationStructureKHR as);

}  // namespace raylab
