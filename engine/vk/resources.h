// Buffers: creation with the right memory, upload and download. Memory is one allocation per buffer, which
// suits raylab's handful of large scene buffers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>

#include "vk/device.h"

namespace raylab {

enum class MemoryUse {
  kDevice,  // device-local; filled by uploads or by the device itself
  kHost,    // host-visible and coherent, persistently mapped (read-back, per-frame data)
};

struct Buffer {
  VkBuffer handle = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;         // non-null when the memory is host-visible
  VkDeviceAddress address = 0;    // when created with VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT
};

// Zero-sized requests get a small buffer, so that an empty scene array still binds.
Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const char* name);
void destroyBuffer(const Device& device, Buffer& buffer);

// Copies host data into the buffer at `offset`: directly when mapped, else through a staging buffer.
void uploadBuffer(const Device& device, const Buffer& buffer, const void* data, VkDeviceSize size,
                  VkDeviceSize offset = 0);
template <class T>
void uploadBuffer(const Device& device, const Buffer& buffer, std::span<const T> data) {
  uploadBuffer(device, buffer, data.data(), data.size_bytes());
}

// Copies `size` bytes from `offset` of the buffer to the host (waits for the device).
void downloadBuffer(const Device& device, const Buffer& buffer, void* data, VkDeviceSize size,
                    VkDeviceSize offset = 0);

// A device-local buffer holding `data`, ready for shaders (and AS builds when usage says so).
template <class T>
Buffer createBufferWithData(const Device& device, std::span<const T> data, VkBufferUsageFlags usage,
                            const char* name) {
  Buffer buffer = createBuffer(device, data.size_bytes(), usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               MemoryUse::kDevice, name);
  if (!data.empty()) uploadBuffer(device, buffer, data.data(), data.size_bytes());
  return buffer;
}

std::uint32_t findMemoryType(const Device& device, std::uint32_t typeBits, VkMemoryPropertyFlags required,
                             VkMemoryPropertyFlags preferred);

}  // namespace raylab
