#include "vk/vk_check.h"

#include <atomic>
#include <cstring>
#include <string>

#include "util/error.h"

namespace raylab {

const char* vkResultName(VkResult result) {
  switch (result) {
#define RAYLAB_RESULT_NAME(name) \
  case name:                     \
    return #name;
    RAYLAB_RESULT_NAME(VK_SUCCESS)
    RAYLAB_RESULT_NAME(VK_NOT_READY)
    RAYLAB_RESULT_NAME(VK_TIMEOUT)
    RAYLAB_RESULT_NAME(VK_EVENT_SET)
    RAYLAB_RESULT_NAME(VK_EVENT_RESET)
    RAYLAB_RESULT_NAME(VK_INCOMPLETE)
    RAYLAB_RESULT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
    RAYLAB_RESULT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    RAYLAB_RESULT_NAME(VK_ERROR_INITIALIZATION_FAILED)
    RAYLAB_RESULT_NAME(VK_ERROR_DEVICE_LOST)
    RAYLAB_RESULT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
    RAYLAB_RESULT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
    RAYLAB_RESULT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    RAYLAB_RESULT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
    RAYLAB_RESULT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    RAYLAB_RESULT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
    RAYLAB_RESULT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    RAYLAB_RESULT_NAME(VK_ERROR_FRAGMENTED_POOL)
    RAYLAB_RESULT_NAME(VK_ERROR_UNKNOWN)
    RAYLAB_RESULT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
    RAYLAB_RESULT_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    RAYLAB_RESULT_NAME(VK_ERROR_FRAGMENTATION)
    RAYLAB_RESULT_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    RAYLAB_RESULT_NAME(VK_PIPELINE_COMPILE_REQUIRED)
    RAYLAB_RESULT_NAME(VK_ERROR_SURFACE_LOST_KHR)
    RAYLAB_RESULT_NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    RAYLAB_RESULT_NAME(VK_SUBOPTIMAL_KHR)
    RAYLAB_RESULT_NAME(VK_ERROR_OUT_OF_DATE_KHR)
    RAYLAB_RESULT_NAME(VK_ERROR_VALIDATION_FAILED_EXT)
    RAYLAB_RESULT_NAME(VK_THREAD_IDLE_KHR)
    RAYLAB_RESULT_NAME(VK_THREAD_DONE_KHR)
    RAYLAB_RESULT_NAME(VK_OPERATION_DEFERRED_KHR)
    RAYLAB_RESULT_NAME(VK_OPERATION_NOT_DEFERRED_KHR)
#undef RAYLAB_RESULT_NAME
    default:
      return "VkResult(unknown)";
  }
}

void failVulkanCall(const char* call, VkResult result, const char* file, int line) {
  throw Error(std::string(file) + ":" + std::to_string(line) + ": " + call + " failed with " + vkResultName(result) +
              " (" + std::to_string(static_cast<int>(result)) + ")");
}

namespace {

std::atomic<unsigned> failAt{0};  // 0: off
std::atomic<unsigned> creations{0};

}  // namespace

void failAtCreation(unsigned n) {
  creations = 0;
  failAt = n;
}

bool injectedCreationFailure(const char* call) {
  if (failAt.load(std::memory_order_relaxed) == 0) return false;
  if (std::strstr(call, "vkCreate") == nullptr && std::strstr(call, "vkAllocate") == nullptr) return false;
  return ++creations == failAt.load();
}

}  // namespace raylab
