#include "vk/pipeline.h"

#include <chrono>
#include <string>

#include "shader_registry.h"
#include "util/error.h"
#include "vk/debug_name.h"
#include "vk/kernel_log.h"
#include "vk/pipeline_store.h"
#include "vk/spirv_specialization.h"
#include "vk/vk_check.h"

namespace raylab {

SpecializationConstants& SpecializationConstants::set(std::uint32_t id, std::uint32_t value) {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i].constantID == id) {
      values_[i] = value;
      return *this;
    }
  }
  entries_.push_back({id, static_cast<std::uint32_t>(values_.size() * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
  values_.push_back(value);
  return *this;
}

const VkSpecializationInfo* SpecializationConstants::info() {
  info_.mapEntryCount = static_cast<std::uint32_t>(entries_.size());
  info_.pMapEntries = entries_.data();
  info_.dataSize = values_.size() * sizeof(std::uint32_t);
  info_.pData = values_.data();
  return &info_;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> SpecializationConstants::values() const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < entries_.size(); ++i) pairs.emplace_back(entries_[i].constantID, values_[i]);
  return pairs;
}

PipelineStore& storeOf(const Device& device) {
  if (!device.pipelines) throw Error("the device has no pipeline store: it was not made by createDevice");
  return *device.pipelines;
}

VkDescriptorSetLayout descriptorSetLayoutFor(const Device& device, std::span<const DescriptorBinding> bindings,
                                             const char* name, VkShaderStageFlags stages) {
  std::string key = "stages " + std::to_string(stages);
  for (const DescriptorBinding& binding : bindings) {
    key += " " + std::to_string(binding.binding) + ":" + std::to_string(binding.type);
  }
  return storeOf(device).setLayout(key, [&] {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    for (const DescriptorBinding& binding : bindings) {
      layoutBindings.push_back({binding.binding, binding.type, 1, stages, nullptr});
    }
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
    info.pBindings = layoutBindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(device.handle, &info, nullptr, &layout));
    setDebugName(device, layout, name);
    return layout;
  });
}

VkPipelineLayout pipelineLayoutFor(const Device& device, VkDescriptorSetLayout setLayout,
                                   std::uint32_t pushConstantBytes, const char* name, VkShaderStageFlags stages) {
  const std::string key = std::to_string(reinterpret_cast<std::uintptr_t>(setLayout)) + " push " +
                          std::to_string(pushConstantBytes) + " stages " + std::to_string(stages);
  return storeOf(device).pipelineLayout(key, [&] {
    const VkPushConstantRange range{stages, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &setLayout;
    info.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(device.handle, &info, nullptr, &layout));
    setDebugName(device, layout, name);
    return layout;
  });
}

namespace {

// The kernel's SPIR-V with `constants` applied; `storage` holds it when they are given.
std::span<const std::uint32_t> specializedSpirv(std::string_view kernelName, const SpecializationConstants* constants,
                                                std::vector<std::uint32_t>& storage) {
  std::span<const std::uint32_t> spirv = embeddedSpirv(kernelName);
  if (spirv.empty()) throw Error("kernel " + std::string(kernelName) + " is not embedded in this build");
  if (constants == nullptr) return spirv;
  storage = specializeSpirv(spirv, constants->values(), kernelName);
  return storage;
}

}  // namespace

std::uint64_t specializedKernelDigest(std::string_view kernelName, const SpecializationConstants* constants,
                                      std::uint64_t digest) {
  std::vector<std::uint32_t> storage;
  digest = kernelDigest(specializedSpirv(kernelName, constants, storage), digest);
  if (constants == nullptr) return digest;
  std::vector<std::uint32_t> values;
  for (const auto& [id, value] : constants->values()) values.insert(values.end(), {id, value});
  return kernelDigest(values, digest);
}

VkShaderModule createShaderModule(const Device& device, std::string_view kernelName,
                                  const SpecializationConstants* constants) {
  std::vector<std::uint32_t> storage;
  const std::span<const std::uint32_t> spirv = specializedSpirv(kernelName, constants, storage);
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirv.size_bytes();
  moduleInfo.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.handle, &moduleInfo, nullptr, &module));
  setDebugName(device, module, std::string(kernelName).c_str());
  return module;
}

std::string kernelKey(std::string_view kernelName, const SpecializationConstants* constants) {
  std::string key(kernelName);
  if (constants == nullptr) return key;
  for (const auto& [id, value] : constants->values()) key += " " + std::to_string(id) + "=" + std::to_string(value);
  return key;
}

VkPipeline acquireComputePipeline(const Device& device, VkPipelineLayout layout, std::string_view kernelName,
                                  SpecializationConstants* constants) {
  return storeOf(device).acquire(device.handle, layout, "compute " + kernelKey(kernelName, constants), [&] {
    const std::string name(kernelName);
    const VkShaderModule module = createShaderModule(device, kernelName, constants);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = constants != nullptr ? constants->info() : nullptr;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const auto started = std::chrono::steady_clock::now();
    const VkResult result =
        injectedCreationFailure("vkCreateComputePipelines")
            ? VK_ERROR_OUT_OF_DEVICE_MEMORY
            : vkCreateComputePipelines(device.handle, device.pipelineCache, 1, &info, nullptr, &pipeline);
    if (kernelLogPath() != nullptr && result == VK_SUCCESS) {
      logKernelCompilation(kernelName, specializedKernelDigest(kernelName, constants, kernelDigest({})),
                           std::chrono::steady_clock::now() - started);
    }
    vkDestroyShaderModule(device.handle, module, nullptr);
    VK_CHECK(result);
    setDebugName(device, pipeline, name.c_str());
    return pipeline;
  });
}

void releasePipeline(const Device& device, VkPipeline pipeline) {
  if (pipeline != VK_NULL_HANDLE) storeOf(device).release(device.handle, pipeline);
}

DescriptorSet allocateDescriptorSet(const Device& device, VkDescriptorSetLayout layout,
                                    std::span<const DescriptorBinding> bindings, const char* name) {
  std::vector<VkDescriptorPoolSize> sizes;
  for (const DescriptorBinding& binding : bindings) sizes.push_back({binding.type, 1});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  DescriptorSet result;
  VK_CHECK(vkCreateDescriptorPool(device.handle, &poolInfo, nullptr, &result.pool));
  setDebugName(device, result.pool, name);

  VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocateInfo.descriptorPool = result.pool;
  allocateInfo.descriptorSetCount = 1;
  allocateInfo.pSetLayouts = &layout;
  try {
    VK_CHECK(vkAllocateDescriptorSets(device.handle, &allocateInfo, &result.set));
  } catch (...) {
    destroyDescriptorSet(device, result);
    throw;
  }
  setDebugName(device, result.set, name);
  return result;
}

void destroyDescriptorSet(const Device& device, DescriptorSet& set) {
  if (set.pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(device.handle, set.pool, nullptr);
  set = {};
}

void writeStorageBuffer(const Device& device, VkDescriptorSet set, std::uint32_t binding, VkBuffer buffer) {
  const VkDescriptorBufferInfo bufferInfo{buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &bufferInfo;
  vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

void writeAccelerationStructure(const Device& device, VkDescriptorSet set, std::uint32_t binding,
                                VkAccelerationStructureKHR as) {
  VkWriteDescriptorSetAccelerationStructureKHR asInfo{
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  asInfo.accelerationStructureCount = 1;
  asInfo.pAccelerationStructures = &as;
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.pNext = &asInfo;
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

}  // namespace raylab
