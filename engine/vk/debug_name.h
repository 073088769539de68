// Debug names for Vulkan objects, so validation messages and captures say which buffer or pipeline is meant.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "vk/device.h"

namespace raylab {

void setDebugName(const Device& device, VkObjectType type, std::uint64_t handle, const char* name);

inline void setDebugName(const Device& d, VkBuffer h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkDeviceMemory h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkImage h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkPipeline h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkPipelineLayout h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_PIPELINE_LAYOUT, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkShaderModule h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkDescriptorSetLayout h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkDescriptorPool h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_DESCRIPTOR_POOL, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkDescriptorSet h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_DESCRIPTOR_SET, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkAccelerationStructureKHR h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkImageView h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<std::uint64_t>(h), n);
}
inline void setDebugName(const Device& d, VkSampler h, const char* n) {
  setDebugName(d, VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<std::uint64_t>(h), n);
}

}  // namespace raylab
