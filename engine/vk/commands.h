// One-shot command submission: record, submit, wait. raylab's offscreen work is synchronous at the host;
// the viewer keeps its own per-frame command buffers.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>

#include "vk/device.h"

namespace raylab {

void submitAndWait(const Device& device, const std::function<void(VkCommandBuffer)>& record);

// Makes shader (compute or ray-tracing) and transfer writes visible to later shaders, transfers and host reads.
void computeBarrier(VkCommandBuffer cmd);

// One layout transition of a whole single-mip colour image, between the given stages and accesses.
struct ImageTransition {
  VkPipelineStageFlags srcStage;
  VkAccessFlags srcAccess;
  VkImageLayout oldLayout;
  VkPipelineStageFlags dstStage;
  VkAccessFlags dstAccess;
  VkImageLayout newLayout;
};
void imageBarrier(VkCommandBuffer cmd, VkImage image, const ImageTransition& transition);

}  // namespace raylab
