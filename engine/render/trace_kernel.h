// A kernel that traces rays through the scene on either backend: one descriptor set (the scene's bindings and
// the kernel's own), push constants, and either a compute pipeline (ray queries) or a ray-tracing pipeline with
// its shader binding table, one hit record per TLAS instance. The renderer and the ray probe are built on it,
// each naming its programs once for both backends (TracePrograms).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "render/backend.h"
#include "render/gpu_scene.h"
#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/ray_tracing_pipeline.h"

namespace raylab {

// The same programs as a compute entry point and as ray-tracing stages (shaders/*.comp, *.rgen, *.rchit, ...).
struct TracePrograms {
  std::string_view compute;
  std::uint32_t workgroupX = 1;  // the compute entry point's local size
  std::uint32_t workgroupY = 1;
  RayTracingProgram pipeline;    // hit groups gpu::kHitGroupTriangles and gpu::kHitGroupSpheres, in that order
};

struct TraceKernel {
  Backend backend = Backend::kQuery;
  const TracePrograms* programs = nullptr;  // static storage
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  DescriptorSet descriptors;
  std::uint32_t pushConstantBytes = 0;
  VkShaderStageFlags stages = 0;           // of the set layout and the push constants
  ShaderBindingTable sbt;                  // the pipeline backend's
  std::vector<HitRecord> hitRecords;       // the pipeline backend's: one per TLAS instance of the scene
  PFN_vkCmdTraceRaysKHR cmdTraceRays = nullptr;
};

// The layouts and the set, without a pipeline yet (acquireTracePipeline, replaceTracePipeline). `programs` must
// outlive the kernel. The scene's TLAS instances decide the hit records; its buffers are not bound here
// (writeSceneDescriptors does that).
TraceKernel createTraceKernel(const Device& device, Backend backend, const TracePrograms& programs,
                              std::span<const DescriptorBinding> bindings, std::uint32_t pushConstantBytes,
                              const GpuScene& gpuScene);
void destroyTraceKernel(const Device& device, TraceKernel& kernel);

// A pipeline of the kernel's layout with other specialization constants, the device's stored one where it built it
// before (vk/pipeline_store.h); thread-safe, for building one in the background (the viewer). On lavapipe the
// driver compiles a new one at its first use, not here.
VkPipeline acquireTracePipeline(const Device& device, const TraceKernel& kernel, SpecializationConstants* constants);
// Installs `pipeline` (the old one is released: the device must not be using it; VK_NULL_HANDLE leaves none);
// the pipeline backend rebuilds its shader binding table, whose handles belong to the pipeline.
void replaceTracePipeline(const Device& device, TraceKernel& kernel, VkPipeline pipeline);

// Binds the kernel and its set, pushes `push` and traces width x height invocations (compute: rounded up to
// whole workgroups; entry points check their bounds). No barrier.
void recordTrace(VkCommandBuffer cmd, const TraceKernel& kernel, const void* push, std::uint32_t width,
                 std::uint32_t height);

}  // namespace raylab
