// A compute kernel ready to dispatch: its descriptor set layout, pipeline layout (one set, optional push
// constants), pipeline and one descriptor set. Every kernel of raylab is one of these; the caller owns the
// buffers it binds. The layouts and the pipeline are the device's (vk/pipeline_store.h): the kernel owns its set
// and one use of the pipeline.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

#include "vk/device.h"
#include "vk/pipeline.h"

namespace raylab {

struct ComputeKernel {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  DescriptorSet descriptors;
  std::uint32_t pushConstantBytes = 0;
};

// `kernelName` names the embedded kernel (shaders/<kernelName>) and every object's debug name.
ComputeKernel createComputeKernel(const Device& device, std::string_view kernelName,
                                  std::span<const DescriptorBinding> bindings, std::uint32_t pushConstantBytes,
                                  SpecializationConstants* constants = nullptr);
void destroyComputeKernel(const Device& device, ComputeKernel& kernel);

// Binds the kernel and its set, pushes `push` (pushConstantBytes of it) and dispatches. No barrier.
void recordDispatch(VkCommandBuffer cmd, const ComputeKernel& kernel, const void* push, std::uint32_t groupsX,
                    std::uint32_t groupsY = 1);

}  // namespace raylab
