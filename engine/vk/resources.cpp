#include "vk/resources.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include "util/error.h"
#include "vk/commands.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

std::uint32_t findMemoryType(const Device& device, std::uint32_t typeBits, VkMemoryPropertyFlags required,
                             VkMemoryPropertyFlags preferred) {
  for (VkMemoryPropertyFlags wanted : {required | preferred, required}) {
    for (std::uint32_t i = 0; i < device.memory.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) && (device.memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
  }
  throw Error("the Vulkan device has no memory type with the properties raylab needs");
}

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const char* name) {
  Buffer buffer;
  buffer.size = std::max<VkDeviceSize>(size, 16);

  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = buffer.size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(device.handle, &info, nullptr, &buffer.handle));

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device.handle, buffer.handle, &requirements);
  const VkMemoryPropertyFlags required =
      use == MemoryUse::kHost ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                              : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  // Host-visible device-local memory (CPUs, UMA, ReBAR) lets uploads skip the staging copy.
  const VkMemoryPropertyFlags preferred =
      use == MemoryUse::kHost ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                              : VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const std::uint32_t typeIndex = findMemoryType(device, requirements.memoryTypeBits, required, preferred);

  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocateInfo.pNext = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) ? &flags : nullptr;
  allocateInfo.allocationSize = requirements.size;
  allocateInfo.memoryTypeIndex = typeIndex;
  // Running out of memory is the input's size, not a bug: say what was being allocated and how much.
  const VkResult allocated = injectedCreationFailure("vkAllocateMemory")
                                 ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                 : vkAllocateMemory(device.handle, &allocateInfo, nullptr, &buffer.memory);
  if (allocated == VK_ERROR_OUT_OF_DEVICE_MEMORY || allocated == VK_ERROR_OUT_OF_HOST_MEMORY) {
    vkDestroyBuffer(device.handle, buffer.handle, nullptr);
    char size[32];
    std::snprintf(size, sizeof size, "%.1f MiB", double(requirements.size) / (1024.0 * 1024.0));
    throw Error(std::string("the Vulkan device is out of memory: allocating ") + size + " for the " + name +
                " buffer failed; render a smaller image or scene");
  }
  VK_CHECK(allocated);
  VK_CHECK(vkBindBufferMemory(device.handle, buffer.handle, buffer.memory, 0));

  const VkMemoryPropertyFlags properties = device.memory.memoryTypes[typeIndex].propertyFlags;
  if ((properties & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) && (properties & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)) {
    VK_CHECK(vkMapMemory(device.handle, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
  }
  if (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) {
    VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    addressInfo.buffer = buffer.handle;
    buffer.address = vkGetBufferDeviceAddress(device.handle, &addressInfo);
  }
  setDebugName(device, buffer.handle, name);
  setDebugName(device, buffer.memory, name);
  return buffer;
}

void destroyBuffer(const Device& device, Buffer& buffer) {
  if (buffer.handle == VK_NULL_HANDLE) return;
  vkDestroyBuffer(device.handle, buffer.handle, nullptr);
  vkFreeMemory(device.handle, buffer.memory, nullptr);
  buffer = {};
}

void uploadBuffer(const Device& device, const Buffer& buffer, const void* data, VkDeviceSize size,
                  VkDeviceSize offset) {
  if (size == 0) return;
  if (buffer.mapped != nullptr) {
    std::memcpy(static_cast<char*>(buffer.mapped) + offset, data, size);
    return;
  }
  Buffer staging = createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::kHost, "staging upload");
  std::memcpy(staging.mapped, data, size);
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, offset, size};
    vkCmdCopyBuffer(cmd, staging.handle, buffer.handle, 1, &region);
  });
  destroyBuffer(device, staging);
}

void downloadBuffer(const Device& device, const Buffer& buffer, void* data, VkDeviceSize size, VkDeviceSize offset) {
  if (size == 0) return;
  if (buffer.mapped != nullptr) {
    std::memcpy(data, static_cast<const std::byte*>(buffer.mapped) + offset, size);
    return;
  }
  Buffer staging =
      createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kHost, "staging download");
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{offset, 0, size};
    vkCmdCopyBuffer(cmd, buffer.handle, staging.handle, 1, &region);
    computeBarrier(cmd);
  });
  std::memcpy(data, staging.mapped, size);
  destroyBuffer(device, staging);
}

}  // namespace raylab
