// VK_CHECK: every Vulkan call whose failure is a bug or an unrecoverable condition goes through it, in every
// build type. Results that may legitimately fail (swapchain out of date) are handled by name at the call site.
#pragma once

#include <vulkan/vulkan.h>

namespace raylab {

// "VK_ERROR_DEVICE_LOST" for VK_ERROR_DEVICE_LOST.
const char* vkResultName(VkResult result);

// Throws raylab::Error naming the call, the result and where it happened.
[[noreturn]] void failVulkanCall(const char* call, VkResult result, const char* file, int line);

// A test hook for clean-up on failure: the Nth call that creates or allocates a Vulkan object from now on
// (vkCreate..., vkAllocate..., on any thread) fails with
// VK_ERROR_OUT_OF_DEVICE_MEMORY before it runs; 0 turns the hook off. Tests set it (tests/gpu/failure_test.cpp).
void failAtCreation(unsigned n);
// Counts a creating call and says whether it is the one to fail (VK_CHECK asks before every call).
bool injectedCreationFailure(const char* call);

}  // namespace raylab

#define VK_CHECK(call)                                                                                     \
  do {                                                                                                     \
    if (::raylab::injectedCreationFailure(#call)) {                                                        \
      ::raylab::failVulkanCall(#call, VK_ERROR_OUT_OF_DEVICE_MEMORY, __FILE__, __LINE__);                   \
    }                                                                                                      \
    const VkResult vkCheckResult_ = (call);                                                                \
    if (vkCheckResult_ != VK_SUCCESS) ::raylab::failVulkanCall(#call, vkCheckResult_, __FILE__, __LINE__); \
  } while (0)
