// Vulkan instance and device creation for raylab: a device must support acceleration structures, buffer device
// addresses, the scalar block layout, and ray queries or ray-tracing pipelines (the two backends). Thin free
// functions over plain structs.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

class PipelineStore;  // vk/pipeline_store.h

struct InstanceOptions {
  bool validation = false;                   // also forced on by RAYLAB_VALIDATION=1
  std::vector<const char*> extensions;       // e.g. the surface extensions GLFW asks for
};

struct Instance {
  VkInstance handle = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  bool validation = false;
  bool debugUtils = false;  // object names and the validation messenger
};

// What raylab found out about one physical device.
struct DeviceReport {
  std::uint32_t index = 0;
  std::string name;
  std::string driver;  // driver name and version string, e.g. "llvmpipe, Mesa 25.0.7 (LLVM 15.0.6)"
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t apiVersion = 0;
  // The two ways of tracing rays it offers; raylab has a backend for each (render/backend.h) and runs on a
  // device with either.
  bool rayQueries = false;           // VK_KHR_ray_query with its rayQuery feature
  bool rayQueriesHidden = false;     // it has them, but RAYLAB_HIDE_RAY_QUERIES=1 makes raylab ignore them
  bool rayTracingPipelines = false;  // VK_KHR_ray_tracing_pipeline with its rayTracingPipeline feature
  std::uint32_t maxRayRecursionDepth = 0;
  std::uint64_t maxStorageBufferRange = 0;  // what one buffer a kernel binds may hold: scene limits before loading
  bool subgroupOperations = false;   // arithmetic and ballot in compute shaders: the ray-query kernels sum their
                                     // ray counts and compact the wavefront's queues with them
  std::vector<std::string> missing;  // what stops raylab from using it; empty when capable
  bool capable() const { return missing.empty(); }
  bool queryBackend() const { return capable() && rayQueries && subgroupOperations; }
  bool pipelineBackend() const { return capable() && rayTracingPipelines; }
};

// The environment variable that hides ray queries from raylab's device survey, to try the pipeline backend as
// a device without ray queries would run it (NVIDIA's data-centre GPUs expose pipelines only).
inline constexpr const char* kHideRayQueriesVariable = "RAYLAB_HIDE_RAY_QUERIES";

// Extension entry points that the loader does not export.
struct ExtensionFunctions {
  PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR getAccelerationStructureBuildSizes = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmdBuildAccelerationStructures = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureDeviceAddress = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT setDebugUtilsObjectName = nullptr;  // null without VK_EXT_debug_utils
  // Null unless the device was created with ray-tracing pipelines.
  PFN_vkCreateRayTracingPipelinesKHR createRayTracingPipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR getRayTracingShaderGroupHandles = nullptr;
  PFN_vkCmdTraceRaysKHR cmdTraceRays = nullptr;
};

// The shader-binding-table layout rules (VkPhysicalDeviceRayTracingPipelinePropertiesKHR).
struct RayTracingLimits {
  std::uint32_t shaderGroupHandleSize = 0;
  std::uint32_t shaderGroupHandleAlignment = 1;
  std::uint32_t shaderGroupBaseAlignment = 1;
  std::uint32_t maxShaderGroupStride = 0;
};

struct Device {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice handle = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;  // graphics+compute where available: the viewer presents from it too
  std::uint32_t queueFamily = 0;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  // Every pipeline is created through it. On lavapipe it saves nothing measurable (a kernel created again is
  // translated from SPIR-V again); `pipelines` is what finds a kernel built before.
  VkPipelineCache pipelineCache = VK_NULL_HANDLE;
  // The layouts and the pipelines the device has built, for reuse (vk/pipeline_store.h); shared by copies of
  // this struct, destroyed by destroyDevice.
  std::shared_ptr<PipelineStore> pipelines;
  DeviceReport report;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  std::uint32_t scratchAlignment = 1;  // minAccelerationStructureScratchOffsetAlignment
  // Limits the renderer must stay within (VkPhysicalDeviceAccelerationStructurePropertiesKHR); the storage
  // buffer range is properties.limits.maxStorageBufferRange.
  std::uint64_t maxPrimitiveCount = 0;
  std::uint64_t maxInstanceCount = 0;
  std::uint32_t subgroupSize = 1;
  // Which ray-tracing interfaces were enabled: each one the report offers (hidden ray queries excepted).
  bool rayQueries = false;
  bool rayTracingPipelines = false;
  bool shaderClock = false;  // VK_KHR_shader_clock's device clock, where offered (raylab render --heatmap)
  RayTracingLimits rayTracing;
  ExtensionFunctions ext;
};

// Throws Error(kExitNoDevice) when there is no Vulkan driver at all.
Instance createInstance(const InstanceOptions& options);
void destroyInstance(Instance& instance);

// Every physical device with what it lacks; `surface` adds presentation support to the requirements.
std::vector<DeviceReport> surveyDevices(const Instance& instance, VkSurfaceKHR surface = VK_NULL_HANDLE);

// The requested device, or the first capable one preferring discrete GPUs. Throws Error(kExitNoDevice)
// with one sentence naming what is missing and how to get it.
std::uint32_t chooseDevice(const std::vector<DeviceReport>& reports, std::optional<std::uint32_t> requested);

Device createDevice(const Instance& instance, const DeviceReport& report, VkSurfaceKHR surface = VK_NULL_HANDLE);
void destroyDevice(Device& device);

// Validation messages (warnings and errors) reported since start-up, from every instance.
std::uint32_t validationMessageCount();

// The one sentence printed when no device can run raylab.
std::string noCapableDeviceMessage(const std::vector<DeviceReport>& reports);

const char* deviceTypeName(VkPhysicalDeviceType type);

}  // namespace raylab
