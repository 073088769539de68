#include "vk/ray_tracing_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>

#include "util/error.h"
#include "vk/debug_name.h"
#include "vk/kernel_log.h"
#include "vk/pipeline.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }

VkPipelineShaderStageCreateInfo stageInfo(VkShaderStageFlagBits stage, VkShaderModule module,
                                          SpecializationConstants* constants) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = stage;
  info.module = module;
  info.pName = "main";
  info.pSpecializationInfo = constants != nullptr ? constants->info() : nullptr;
  return info;
}

VkRayTracingShaderGroupCreateInfoKHR generalGroup(std::uint32_t stage) {
  VkRayTracingShaderGroupCreateInfoKHR group{VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
  group.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
  group.generalShader = stage;
  group.closestHitShader = VK_SHADER_UNUSED_KHR;
  group.anyHitShader = VK_SHADER_UNUSED_KHR;
  group.intersectionShader = VK_SHADER_UNUSED_KHR;
  return group;
}

std::uint32_t groupCount(const RayTracingProgram& program) {
  return static_cast<std::uint32_t>(1 + program.misses.size() + program.hitGroups.size());
}

}  // namespace

VkPipeline acquireRayTracingPipeline(const Device& device, VkPipelineLayout layout, const RayTracingProgram& program,
                                    SpecializationConstants* constants, const char* name) {
  if (!device.rayTracingPipelines) {
    throw Error(std::string("the device was created without ray-tracing pipelines; ") + name + " needs them");
  }
  if (program.maxRecursionDepth > device.report.maxRayRecursionDepth) {
    throw Error(std::string(name) + " needs a ray recursion depth of " + std::to_string(program.maxRecursionDepth) +
                ", over this device's maxRayRecursionDepth of " + std::to_string(device.report.maxRayRecursionDepth));
  }
  // The key: every stage's kernel in order, the recursion depth and the constants.
  std::string key = "ray tracing depth " + std::to_string(program.maxRecursionDepth) + " " +
                    kernelKey(program.raygen, constants);
  for (std::string_view miss : program.misses) key += " miss " + std::string(miss);
  for (const RayTracingProgram::HitGroup& hitGroup : program.hitGroups) {
    key += " group " + std::string(hitGroup.closestHit) + "," + std::string(hitGroup.anyHit) + "," +
           std::string(hitGroup.intersection);
  }
  return storeOf(device).acquire(device.handle, layout, key, [&] {
    // Stages in order: raygen, misses, then each hit group's closest hit, any hit and intersection; groups likewise.
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
    const auto addStage = [&](std::string_view kernel, VkShaderStageFlagBits stage) {
      modules.push_back(createShaderModule(device, kernel, constants));
      stages.push_back(stageInfo(stage, modules.back(), constants));
      return static_cast<std::uint32_t>(stages.size() - 1);
    };
    VkPipeline pipeline = VK_NULL_HANDLE;
    try {
      groups.push_back(generalGroup(addStage(program.raygen, VK_SHADER_STAGE_RAYGEN_BIT_KHR)));
      for (std::string_view miss : program.misses) groups.push_back(generalGroup(addStage(miss, VK_SHADER_STAGE_MISS_BIT_KHR)));
      for (const RayTracingProgram::HitGroup& hitGroup : program.hitGroups) {
        VkRayTracingShaderGroupCreateInfoKHR group{VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
        group.type = hitGroup.intersection.empty() ? VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR
                                                   : VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR;
        group.generalShader = VK_SHADER_UNUSED_KHR;
        group.closestHitShader = addStage(hitGroup.closestHit, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR);
        group.anyHitShader =
            hitGroup.anyHit.empty() ? VK_SHADER_UNUSED_KHR : addStage(hitGroup.anyHit, VK_SHADER_STAGE_ANY_HIT_BIT_KHR);
        group.intersectionShader = hitGroup.intersection.empty()
                                       ? VK_SHADER_UNUSED_KHR
                                       : addStage(hitGroup.intersection, VK_SHADER_STAGE_INTERSECTION_BIT_KHR);
        groups.push_back(group);
      }

      VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
      info.stageCount = static_cast<std::uint32_t>(stages.size());
      info.pStages = stages.data();
      info.groupCount = static_cast<std::uint32_t>(groups.size());
      info.pGroups = groups.data();
      info.maxPipelineRayRecursionDepth = program.maxRecursionDepth;
      info.layout = layout;
      const auto started = std::chrono::steady_clock::now();
      VK_CHECK(device.ext.createRayTracingPipelines(device.handle, VK_NULL_HANDLE, device.pipelineCache, 1, &info, nullptr,
                                                    &pipeline));
      if (kernelLogPath() != nullptr) {
        std::uint64_t digest = specializedKernelDigest(program.raygen, constants, kernelDigest({}));
        for (std::string_view miss : program.misses) digest = specializedKernelDigest(miss, constants, digest);
        for (const RayTracingProgram::HitGroup& hitGroup : program.hitGroups) {
          for (std::string_view kernel : {hitGroup.closestHit, hitGroup.anyHit, hitGroup.intersection}) {
            if (!kernel.empty()) digest = specializedKernelDigest(kernel, constants, digest);
          }
        }
        logKernelCompilation(program.raygen, digest, std::chrono::steady_clock::now() - started);
      }
    } catch (...) {
      for (VkShaderModule module : modules) vkDestroyShaderModule(device.handle, module, nullptr);
      throw;
    }
    for (VkShaderModule module : modules) vkDestroyShaderModule(device.handle, module, nullptr);
    setDebugName(device, pipeline, name);
    return pipeline;
  });
}

ShaderBindingTable createShaderBindingTable(const Device& device, VkPipeline pipeline, const RayTracingProgram& program,
                                            std::span<const HitRecord> hits, std::uint32_t dataBytes,
                                            const char* name) {
  const VkDeviceSize handleSize = device.rayTracing.shaderGroupHandleSize;
  const VkDeviceSize baseAlignment = device.rayTracing.shaderGroupBaseAlignment;
  const std::uint32_t groups = groupCount(program);
  std::vector<std::uint8_t> handles(groups * handleSize);
  VK_CHECK(device.ext.getRayTracingShaderGroupHandles(device.handle, pipeline, 0, groups, handles.size(),
                                                      handles.data()));

  ShaderBindingTable table;
  const VkDeviceSize handleStride = alignUp(handleSize, device.rayTracing.shaderGroupHandleAlignment);
  const VkDeviceSize hitStride = alignUp(handleSize + dataBytes, device.rayTracing.shaderGroupHandleAlignment);
  if (hitStride > device.rayTracing.maxShaderGroupStride) {
    throw Error(std::string(name) + ": a hit record of " + std::to_string(hitStride) + " bytes exceeds maxShaderGroupStride");
  }
  // Each region starts on the base alignment; the raygen region's size must equal its stride.
  table.raygen = {0, alignUp(handleSize, baseAlignment), alignUp(handleSize, baseAlignment)};
  table.miss = {0, handleStride, handleStride * program.misses.size()};
  table.hit = {0, hitStride, hitStride * std::max<std::size_t>(hits.size(), 1)};
  const VkDeviceSize missOffset = table.raygen.size;
  const VkDeviceSize hitOffset = alignUp(missOffset + table.miss.size, baseAlignment);
  std::vector<std::uint8_t> bytes(hitOffset + table.hit.size, 0);
  const auto handle = [&](std::uint32_t group) { return handles.data() + group * handleSize; };
  std::memcpy(bytes.data(), handle(0), handleSize);
  for (std::size_t i = 0; i < program.misses.size(); ++i) {
    std::memcpy(bytes.data() + missOffset + i * handleStride, handle(static_cast<std::uint32_t>(1 + i)), handleSize);
  }
  const std::uint32_t firstHitGroup = static_cast<std::uint32_t>(1 + program.misses.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].group >= program.hitGroups.size() || hits[i].data.size() > dataBytes) {
      throw Error(std::string(name) + ": hit record " + std::to_string(i) + " names no hit group or has too much data");
    }
    std::uint8_t* record = bytes.data() + hitOffset + i * hitStride;
    std::memcpy(record, handle(firstHitGroup + hits[i].group), handleSize);
    std::memcpy(record + handleSize, hits[i].data.data(), hits[i].data.size());
  }

  // The table starts at the first address of the buffer on shaderGroupBaseAlignment: the buffer's own
  // alignment need not be that large.
  table.buffer = createBuffer(device, bytes.size() + baseAlignment,
                              VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              MemoryUse::kDevice, name);
  const VkDeviceAddress start = alignUp(table.buffer.address, baseAlignment);
  uploadBuffer(device, table.buffer, bytes.data(), bytes.size(), start - table.buffer.address);
  table.raygen.deviceAddress = start;
  table.miss.deviceAddress = start + missOffset;
  table.hit.deviceAddress = start + hitOffset;
  return table;
}

void destroyShaderBindingTable(const Device& device, ShaderBindingTable& table) {
  destroyBuffer(device, table.buffer);
  table = {};
}

}  // namespace raylab
