// Compute pipelines from embedded SPIR-V, specialization constants, and descriptor sets.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "vk/device.h"

namespace raylab {

// The one helper for specialization constants: kernels are specialised per scene with these (STYLE.md).
class SpecializationConstants {
 public:
  SpecializationConstants& set(std::uint32_t id, std::uint32_t value);
  // Valid while this object lives and is not modified.
  const VkSpecializationInfo* info();

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<std::uint32_t> values_;
  VkSpecializationInfo info_{};
};

struct DescriptorBinding {
  std::uint32_t binding;
  VkDescriptorType type;
};

VkDescriptorSetLayout createDescriptorSetLayout(const Device& device, std::span<const DescriptorBinding> bindings,
                                                const char* name);

// A pipeline layout with one descriptor set and `pushConstantBytes` of compute push constants.
VkPipelineLayout createPipelineLayout(const Device& device, VkDescriptorSetLayout setLayout,
                                      std::uint32_t pushConstantBytes, const char* name);

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
