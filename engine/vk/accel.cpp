#include "vk/accel.h"

#include <string>

#include "util/error.h"
#include "vk/commands.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

AccelerationStructure createAccelerationStructure(const Device& device, VkAccelerationStructureTypeKHR type,
                                                  VkDeviceSize size, const char* name) {
  AccelerationStructure as;
  as.storage = createBuffer(device, size,
                            VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                            MemoryUse::kDevice, name);
  VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  info.buffer = as.storage.handle;
  info.size = size;
  info.type = type;
  try {
    VK_CHECK(device.ext.createAccelerationStructure(device.handle, &info, nullptr, &as.handle));
  } catch (...) {
    destroyBuffer(device, as.storage);
    throw;
  }
  VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  addressInfo.accelerationStructure = as.handle;
  as.address = device.ext.getAccelerationStructureDeviceAddress(device.handle, &addressInfo);
  setDebugName(device, as.handle, name);
  return as;
}

VkAccelerationStructureGeometryKHR describeGeometry(const BlasInput& input) {
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  // Opaque: triangles need no any-hit program; AABB candidates are returned to the kernel regardless.
  geometry.flags = input.opaque || input.kind == BlasInput::Kind::kAabbs ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0u;
  if (input.kind == BlasInput::Kind::kTriangles) {
    geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    auto& triangles = geometry.geometry.triangles;
    triangles.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
    triangles.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    triangles.vertexData.deviceAddress = input.vertices;
    triangles.vertexStride = sizeof(float) * 3;
    triangles.maxVertex = input.vertexCount > 0 ? input.vertexCount - 1 : 0;
    triangles.indexType = VK_INDEX_TYPE_UINT32;
    triangles.indexData.deviceAddress = input.indices;
  } else {
    geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    auto& aabbs = geometry.geometry.aabbs;
    aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
    aabbs.data.deviceAddress = input.aabbs;
    aabbs.stride = sizeof(VkAabbPositionsKHR);
  }
  return geometry;
}

}  // namespace

std::vector<AccelerationStructure> buildBlases(const Device& device, std::span<const BlasInput> inputs) {
  const std::size_t count = inputs.size();
  std::vector<VkAccelerationStructureGeometryKHR> geometries(count);
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> builds(count);
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(count);
  std::vector<VkDeviceSize> scratchOffsets(count);
  std::vector<AccelerationStructure> blases(count);
  Buffer scratch;
  // What was created is released when a later step throws.
  try {
  VkDeviceSize scratchSize = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const BlasInput& input = inputs[i];
    geometries[i] = describeGeometry(input);
    ranges[i] = {};
    ranges[i].primitiveCount =
        input.kind == BlasInput::Kind::kTriangles ? input.triangleCount : input.aabbCount;

    VkAccelerationStructureBuildGeometryInfoKHR& build = builds[i];
    build = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    build.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    build.geometryCount = 1;
    build.pGeometries = &geometries[i];

    VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    device.ext.getAccelerationStructureBuildSizes(device.handle, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                  &build, &ranges[i].primitiveCount, &sizes);
    const std::string name = "BLAS " + std::to_string(i);
    blases[i] = createAccelerationStructure(device, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                            sizes.accelerationStructureSize, name.c_str());
    build.dstAccelerationStructure = blases[i].handle;
    scratchOffsets[i] = scratchSize;
    scratchSize = alignUp(scratchSize + sizes.buildScratchSize, device.scratchAlignment);
  }
  if (count == 0) return blases;

  // The scratch address itself must be aligned too; over-allocate so that any base can be rounded up.
  scratch = createBuffer(device, scratchSize + device.scratchAlignment,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                MemoryUse::kDevice, "BLAS scratch");
  const VkDeviceAddress scratchBase = alignUp(scratch.address, device.scratchAlignment);
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> rangePointers(count);
  for (std::size_t i = 0; i < count; ++i) {
    builds[i].scratchData.deviceAddress = scratchBase + scratchOffsets[i];
    rangePointers[i] = &ranges[i];
  }
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    device.ext.cmdBuildAccelerationStructures(cmd, static_cast<std::uint32_t>(count), builds.data(),
                                              rangePointers.data());
  });
  } catch (...) {
    destroyBuffer(device, scratch);
    for (AccelerationStructure& blas : blases) destroyAccelerationStructure(device, blas);
    throw;
  }
  destroyBuffer(device, scratch);
  return blases;
}

AccelerationStructure buildTlas(const Device& device, std::span<const AccelerationStructure> blases,
                                std::span<const TlasInstance> instances) {
  std::vector<VkAccelerationStructureInstanceKHR> records(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const TlasInstance& instance = instances[i];
    if (instance.customIndex >= (1u << 24) || instance.sbtRecord >= (1u << 24)) {
      throw Error("more than 2^24 instances: the custom index or the SBT record offset overflows");
    }
    VkAccelerationStructureInstanceKHR& record = records[i];
    record = {};
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 4; ++column) record.transform.matrix[row][column] = instance.transform[row][column];
    }
    record.instanceCustomIndex = instance.customIndex;
    record.mask = 0xFF;
    record.instanceShaderBindingTableRecordOffset = instance.sbtRecord;
    // Winding is resolved in the kernel from the geometric normal, so facing culling stays off.
    record.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
    record.accelerationStructureReference = blases[instance.blas].address;
  }
  Buffer instanceBuffer;
  AccelerationStructure tlas;
  Buffer scratch;
  // What was created is released when a later step throws.
  try {
  instanceBuffer = createBufferWithData<VkAccelerationStructureInstanceKHR>(device, records, kAsInputUsage,
                                                                            "TLAS instances");

  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.data.deviceAddress = instanceBuffer.address;

  VkAccelerationStructureBuildGeometryInfoKHR build{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  build.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = 1;
  build.pGeometries = &geometry;

  const std::uint32_t primitiveCount = static_cast<std::uint32_t>(records.size());
  VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  device.ext.getAccelerationStructureBuildSizes(device.handle, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                &build, &primitiveCount, &sizes);
  tlas = createAccelerationStructure(device, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                     sizes.accelerationStructureSize, "TLAS");
  scratch = createBuffer(device, sizes.buildScratchSize + device.scratchAlignment,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                MemoryUse::kDevice, "TLAS scratch");
  build.dstAccelerationStructure = tlas.handle;
  build.scratchData.deviceAddress = alignUp(scratch.address, device.scratchAlignment);

  const VkAccelerationStructureBuildRangeInfoKHR range{primitiveCount, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* rangePointer = &range;
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    device.ext.cmdBuildAccelerationStructures(cmd, 1, &build, &rangePointer);
  });
  } catch (...) {
    destroyBuffer(device, scratch);
    destroyAccelerationStructure(device, tlas);
    destroyBuffer(device, instanceBuffer);
    throw;
  }
  destroyBuffer(device, scratch);
  destroyBuffer(device, instanceBuffer);
  return tlas;
}

void destroyAccelerationStructure(const Device& device, AccelerationStructure& as) {
  if (as.handle != VK_NULL_HANDLE) device.ext.destroyAccelerationStructure(device.handle, as.handle, nullptr);
  destroyBuffer(device, as.storage);
  as = {};
}

}  // namespace raylab
