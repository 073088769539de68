#include "render/trace_kernel.h"

#include <cstring>
#include <string>

#include "shared/ray_tracing.h"
#include "shared/scene_records.h"
#include "vk/debug_name.h"

namespace raylab {

namespace {

VkPipelineBindPoint bindPoint(Backend backend) {
  return backend == Backend::kPipeline ? VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR : VK_PIPELINE_BIND_POINT_COMPUTE;
}

// Hit record i serves TLAS instance i: the hit group of its geometry, and its InstanceRecord as data.
std::vector<HitRecord> hitRecordsOf(const GpuScene& gpuScene) {
  std::vector<HitRecord> records;
  for (std::uint32_t i = 0; i < gpuScene.instanceGeometry.size(); ++i) {
    HitRecord record;
    record.group = gpuScene.instanceGeometry[i] == gpu::kGeometrySpheres ? gpu::kHitGroupSpheres
                                                                         : gpu::kHitGroupTriangles;
    const gpu::HitGroupData data{i};
    record.data.resize(sizeof data);
    std::memcpy(record.data.data(), &data, sizeof data);
    records.push_back(std::move(record));
  }
  return records;
}

std::string kernelName(const TraceKernel& kernel) {
  return std::string(kernel.backend == Backend::kPipeline ? kernel.programs->pipeline.raygen
                                                          : kernel.programs->compute);
}

}  // namespace

TraceKernel createTraceKernel(const Device& device, Backend backend, const TracePrograms& programs,
                              std::span<const DescriptorBinding> bindings, std::uint32_t pushConstantBytes,
                              const GpuScene& gpuScene) {
  TraceKernel kernel;
  kernel.backend = backend;
  kernel.programs = &programs;
  kernel.pushConstantBytes = pushConstantBytes;
  kernel.stages = backend == Backend::kPipeline ? kRayTracingStages : VkShaderStageFlags{VK_SHADER_STAGE_COMPUTE_BIT};
  const std::string name = kernelName(kernel);
  try {
    kernel.setLayout = descriptorSetLayoutFor(device, bindings, (name + " set layout").c_str(), kernel.stages);
    kernel.pipelineLayout = pipelineLayoutFor(device, kernel.setLayout, pushConstantBytes,
                                                 (name + " pipeline layout").c_str(), kernel.stages);
    kernel.descriptors = allocateDescriptorSet(device, kernel.setLayout, bindings, (name + " set").c_str());
    if (backend == Backend::kPipeline) {
      kernel.hitRecords = hitRecordsOf(gpuScene);
      kernel.cmdTraceRays = device.ext.cmdTraceRays;
    }
  } catch (...) {
    destroyTraceKernel(device, kernel);
    throw;
  }
  return kernel;
}

void destroyTraceKernel(const Device& device, TraceKernel& kernel) {
  destroyShaderBindingTable(device, kernel.sbt);
  destroyDescriptorSet(device, kernel.descriptors);
  releasePipeline(device, kernel.pipeline);  // the layouts are the device's (vk/pipeline_store.h)
  kernel = {};
}

VkPipeline acquireTracePipeline(const Device& device, const TraceKernel& kernel, SpecializationConstants* constants) {
  if (kernel.backend == Backend::kPipeline) {
    return acquireRayTracingPipeline(device, kernel.pipelineLayout, kernel.programs->pipeline, constants,
                                    kernelName(kernel).c_str());
  }
  return acquireComputePipeline(device, kernel.pipelineLayout, kernel.programs->compute, constants);
}

void replaceTracePipeline(const Device& device, TraceKernel& kernel, VkPipeline pipeline) {
  if (pipeline == VK_NULL_HANDLE) destroyShaderBindingTable(device, kernel.sbt);
  if (kernel.backend == Backend::kPipeline && pipeline != VK_NULL_HANDLE) {
    ShaderBindingTable sbt;
    try {
      sbt = createShaderBindingTable(device, pipeline, kernel.programs->pipeline, kernel.hitRecords,
                                     sizeof(gpu::HitGroupData), (kernelName(kernel) + " SBT").c_str());
    } catch (...) {
      releasePipeline(device, pipeline);
      throw;
    }
    destroyShaderBindingTable(device, kernel.sbt);
    kernel.sbt = sbt;
  }
  releasePipeline(device, kernel.pipeline);
  kernel.pipeline = pipeline;
}

void recordTrace(VkCommandBuffer cmd, const TraceKernel& kernel, const void* push, std::uint32_t width,
                 std::uint32_t height) {
  const VkPipelineBindPoint point = bindPoint(kernel.backend);
  vkCmdBindPipeline(cmd, point, kernel.pipeline);
  vkCmdBindDescriptorSets(cmd, point, kernel.pipelineLayout, 0, 1, &kernel.descriptors.set, 0, nullptr);
  if (kernel.pushConstantBytes > 0) {
    vkCmdPushConstants(cmd, kernel.pipelineLayout, kernel.stages, 0, kernel.pushConstantBytes, push);
  }
  if (kernel.backend == Backend::kPipeline) {
    kernel.cmdTraceRays(cmd, &kernel.sbt.raygen, &kernel.sbt.miss, &kernel.sbt.hit, &kernel.sbt.callable, width,
                        height, 1);
  } else {
    vkCmdDispatch(cmd, (width + kernel.programs->workgroupX - 1) / kernel.programs->workgroupX,
                  (height + kernel.programs->workgroupY - 1) / kernel.programs->workgroupY, 1);
  }
}

}  // namespace raylab
