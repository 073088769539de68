// raylab_spirv_batch: runs a compute kernel compiled elsewhere (MaterialX's generated GLSL, turned into a compute
// shader by tools/materialx_compare.py) over a batch of cases on the Vulkan device, for the independent
// cross-check of docs/brdfs.md. The kernel reads binding 0 (the cases, IN_STRIDE floats each), writes binding 1
// (OUT_STRIDE floats each), takes the case count as a push constant, and runs 64 invocations a workgroup.
//
//   raylab_spirv_batch KERNEL.spv CASES.f32 OUT.f32 IN_STRIDE OUT_STRIDE
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "vk/commands.h"
#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/resources.h"
#include "vk/vk_check.h"

namespace raylab {
namespace {

constexpr std::uint64_t kMaxKernelBytes = std::uint64_t(64) << 20;
constexpr std::uint32_t kWorkgroupSize = 64;  // the kernel's local_size_x

std::uint32_t strideArgument(const char* text, const char* what) {
  char* end = nullptr;
  const unsigned long value = std::strtoul(text, &end, 10);
  if (end == text || *end != '\0' || value == 0 || value > 1024) {
    throw Error(std::string(what) + " = '" + text + "': expected a count of floats in [1, 1024]");
  }
  return std::uint32_t(value);
}

void run(const std::string& kernelPath, const std::string& casesPath, const std::string& outPath, std::uint32_t inStride,
         std::uint32_t outStride) {
  const std::string spirv = readInputFile(kernelPath, kMaxKernelBytes);
  if (spirv.size() < 20 || spirv.size() % 4 != 0) throw Error(kernelPath + ": not a SPIR-V module");
  const std::string cases = readInputFile(casesPath, kMaxCaseFileBytes);
  if (cases.empty() || cases.size() % (4u * inStride) != 0) {
    throw Error(casesPath + ": " + std::to_string(cases.size()) + " bytes is not a whole number of " +
                std::to_string(inStride) + "-float cases");
  }
  const auto count = std::uint32_t(cases.size() / (4u * inStride));

  Instance instance = createInstance({});
  const std::vector<DeviceReport> reports = surveyDevices(instance);
  Device device = createDevice(instance, reports[chooseDevice(reports, std::nullopt)]);
  const DescriptorBinding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  VkDescriptorSetLayout setLayout = descriptorSetLayoutFor(device, bindings, "materialx batch set layout");
  VkPipelineLayout layout = pipelineLayoutFor(device, setLayout, sizeof(std::uint32_t), "materialx batch layout");
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirv.size();
  std::vector<std::uint32_t> words(spirv.size() / 4);
  std::memcpy(words.data(), spirv.data(), spirv.size());
  moduleInfo.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device.handle, &moduleInfo, nullptr, &module));
  VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipelineInfo.stage.module = module;
  pipelineInfo.stage.pName = "main";
  pipelineInfo.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult created = vkCreateComputePipelines(device.handle, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline);
  vkDestroyShaderModule(device.handle, module, nullptr);
  VK_CHECK(created);
  DescriptorSet set = allocateDescriptorSet(device, setLayout, bindings, "materialx batch set");
  Buffer input = createBuffer(device, cases.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              MemoryUse::kDevice, "materialx cases");
  const VkDeviceSize outBytes = VkDeviceSize(count) * outStride * 4u;
  Buffer output = createBuffer(device, outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               MemoryUse::kDevice, "materialx values");
  writeStorageBuffer(device, set.set, 0, input.handle);
  writeStorageBuffer(device, set.set, 1, output.handle);
  uploadBuffer(device, input, cases.data(), cases.size());
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set.set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(count), &count);
    vkCmdDispatch(cmd, (count + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
    computeBarrier(cmd);
  });
  std::string values(outBytes, '\0');
  downloadBuffer(device, output, values.data(), outBytes);
  writeFileAtomically(outPath, values);

  destroyBuffer(device, output);
  destroyBuffer(device, input);
  destroyDescriptorSet(device, set);
  vkDestroyPipeline(device.handle, pipeline, nullptr);
  // The layouts are the device's (vk/pipeline_store.h).
  destroyDevice(device);
  destroyInstance(instance);
}

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::printf("usage: raylab_spirv_batch KERNEL.spv CASES.f32 OUT.f32 IN_STRIDE OUT_STRIDE\n"
                "Runs a compute kernel (binding 0: the cases, IN_STRIDE floats each; binding 1: OUT_STRIDE floats\n"
                "each; push constant: the case count; 64 invocations a workgroup) on the Vulkan device and writes\n"
                "its output. tools/materialx_compare.py runs MaterialX's GLSL through it.\n");
    return 0;
  }
  if (argc != 6) {
    std::fprintf(stderr, "usage: raylab_spirv_batch KERNEL.spv CASES.f32 OUT.f32 IN_STRIDE OUT_STRIDE\n");
    return 2;
  }
  try {
    raylab::run(argv[1], argv[2], argv[3], raylab::strideArgument(argv[4], "IN_STRIDE"),
                raylab::strideArgument(argv[5], "OUT_STRIDE"));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "raylab_spirv_batch: %s\n", error.what());
    return 2;
  }
  return 0;
}
