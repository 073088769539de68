#include "vk/debug_name.h"

namespace raylab {

void setDebugName(const Device& device, VkObjectType type, std::uint64_t handle, const char* name) {
  if (device.ext.setDebugUtilsObjectName == nullptr || handle == 0) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  device.ext.setDebugUtilsObjectName(device.handle, &info);
}

}  // namespace raylab
