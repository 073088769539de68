// VK_CHECK: every Vulkan call whose failure is a bug or an unrecoverable condition goes through it, in every
// build type. Results that may legitimately fail (swapchain out of date) are handled by name at the call site.
#pragma once

#include <vulkan/vulkan.h>

namespace raylab {

// "VK_ERROR_DEVICE_LOST" for VK_ERROR_DEVICE_LOST.
const char* vkResultName(VkResult result);

// Throws raylab::Error naming the call, the result and where it happened.
[[noreturn]] void failVulkanCall(const char* call, VkResult result, const char* file, int line);

}  // namespace raylab

#define VK_CHECK(call)                                                                   \
  do {                                                                                   \
    const VkResult vkCheckResult_ = (call);                                              \
    if (vkCheckResult_ != VK_SUCCESS) ::raylab::failVulkanCall(#call, vkCheckResult_, __FILE__, __LINE__); \
  } while (0)
