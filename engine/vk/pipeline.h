// Compute pipelines from embedded SPIR-V, specialization constants, and descriptor sets.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vk/device.h"
#include "vk/pipeline_store.h"

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

// The device's set layout of `bindings`, every binding visible to `stages` (compute, or the ray-tracing stages of
// vk/ray_tracing_pipeline.h). The device keeps it (vk/pipeline_store.h): never destroy it. `name` names it when
// this call creates it.
VkDescriptorSetLayout descriptorSetLayoutFor(const Device& device, std::span<const DescriptorBinding> bindings,
                                             const char* name, VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);

// The device's pipeline layout with one descriptor set and `pushConstantBytes` of push constants for `stages`;
// kept by the device like the set layout.
VkPipelineLayout pipelineLayoutFor(const Device& device, VkDescriptorSetLayout setLayout,
                                   std::uint32_t pushConstantBytes, const char* name,
                                   VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);

// A module of the kernel embedded as `kernelName` (shaders/<kernelName>), debug-named after it, specialised on the
// host with `constants` where given (vk/spirv_specialization.h); the caller destroys it once its pipeline exists.
// Throws if it is not embedded.
VkShaderModule createShaderModule(const Device& device, std::string_view kernelName,
                                  const SpecializationConstants* constants = nullptr);

// A digest of the kernel as the driver receives it (specialised SPIR-V and constants), continuing from `digest`:
// what tells two compilations of one kernel apart in the kernel log (vk/kernel_log.h).
std::uint64_t specializedKernelDigest(std::string_view kernelName, const SpecializationConstants* constants,
                                      std::uint64_t digest);

// What tells kernels of one layout apart: the entry point's name and each specialisation constant's value.
std::string kernelKey(std::string_view kernelName, const SpecializationConstants* constants);

// The kernel embedded as `kernelName` (shaders/<kernelName>) specialised with `constants`: the device's stored
// one where it has built it before, else built now (vk/pipeline_store.h). Throws if it is not embedded. Hand it
// back with releasePipeline, never vkDestroyPipeline.
VkPipeline acquireComputePipeline(const Device& device, VkPipelineLayout layout, std::string_view kernelName,
                                  SpecializationConstants* constants = nullptr);

// Ends one use of a pipeline from acquireComputePipeline or acquireRayTracingPipeline (VK_NULL_HANDLE: none). The
// device must not be running it, as for vkDestroyPipeline.
void releasePipeline(const Device& device, VkPipeline pipeline);

// The device's store (vk/pipeline_store.h); throws for a Device that createDevice did not make.
PipelineStore& storeOf(const Device& device);

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
