#include "vk/compute_kernel.h"

#include <string>

namespace raylab {

ComputeKernel createComputeKernel(const Device& device, std::string_view kernelName,
                                  std::span<const DescriptorBinding> bindings, std::uint32_t pushConstantBytes,
                                  SpecializationConstants* constants) {
  const std::string name(kernelName);
  ComputeKernel kernel;
  kernel.pushConstantBytes = pushConstantBytes;
  kernel.setLayout = descriptorSetLayoutFor(device, bindings, (name + " set layout").c_str());
  kernel.pipelineLayout =
      pipelineLayoutFor(device, kernel.setLayout, pushConstantBytes, (name + " pipeline layout").c_str());
  kernel.pipeline = acquireComputePipeline(device, kernel.pipelineLayout, kernelName, constants);
  try {
    kernel.descriptors = allocateDescriptorSet(device, kernel.setLayout, bindings, (name + " set").c_str());
  } catch (...) {
    releasePipeline(device, kernel.pipeline);
    throw;
  }
  return kernel;
}

void destroyComputeKernel(const Device& device, ComputeKernel& kernel) {
  destroyDescriptorSet(device, kernel.descriptors);
  releasePipeline(device, kernel.pipeline);  // the layouts are the device's (vk/pipeline_store.h)
  kernel = {};
}

void recordDispatch(VkCommandBuffer cmd, const ComputeKernel& kernel, const void* push, std::uint32_t groupsX,
                    std::uint32_t groupsY) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipelineLayout, 0, 1, &kernel.descriptors.set,
                          0, nullptr);
  if (kernel.pushConstantBytes > 0) {
    vkCmdPushConstants(cmd, kernel.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, kernel.pushConstantBytes, push);
  }
  vkCmdDispatch(cmd, groupsX, groupsY, 1);
}

}  // namespace raylab
