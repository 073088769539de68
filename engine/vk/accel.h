// Acceleration structures: bottom levels over indexed triangles or over sphere AABBs, and the top level over
// their instances. Everything is built on the device through command buffers (lavapipe has no host builds).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

#include "vk/device.h"
#include "vk/resources.h"

namespace raylab {

struct AccelerationStructure {
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  Buffer storage;
  VkDeviceAddress address = 0;
};

// One bottom level: either an indexed triangle mesh (float3 positions, uint32 indices) or a set of AABBs
// (VkAabbPositionsKHR) whose intersections the kernel's intersectSphere decides.
struct BlasInput {
  enum class Kind { kTriangles, kAabbs } kind = Kind::kTriangles;
  VkDeviceAddress vertices = 0;  // first position of this mesh
  std::uint32_t vertexCount = 0;
  VkDeviceAddress indices = 0;   // first index of this mesh
  std::uint32_t triangleCount = 0;
  VkDeviceAddress aabbs = 0;
  std::uint32_t aabbCount = 0;
  // Triangles only: false for alpha-tested geometry, whose candidates the kernel decides (any-hit, or the ray
  // query's candidate loop); opaque triangles commit inside the traversal.
  bool opaque = true;
};

struct TlasInstance {
  std::uint32_t blas = 0;         // index into the built BLAS list
  float transform[3][4] = {};     // object to world, row-major 3x4 as Vulkan expects
  std::uint32_t customIndex = 0;  // 24 bits: the InstanceRecord of this instance (ray queries read it)
  std::uint32_t sbtRecord = 0;    // 24 bits: its hit-group record in a ray-tracing pipeline's SBT
};

// Builds every BLAS in one submission (they share one scratch buffer, one region each).
std::vector<AccelerationStructure> buildBlases(const Device& device, std::span<const BlasInput> inputs);

AccelerationStructure buildTlas(const Device& device, std::span<const AccelerationStructure> blases,
                                std::span<const TlasInstance> instances);

void destroyAccelerationStructure(const Device& device, AccelerationStructure& as);

// Usage flags for buffers that feed AS builds (positions, indices, AABBs).
inline constexpr VkBufferUsageFlags kAsInputUsage = VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                                    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

}  // namespace raylab
