#include "vk/device.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "util/error.h"
#include "vk/driver_shader_cache.h"
#include "vk/pipeline_store.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kSetupHint = "run `tools/setup.sh render` from the raylab sources to install Mesa's lavapipe "
                                   "with ray tracing (mesa-vulkan-drivers >= 24.1 from bookworm-backports)";

std::atomic<std::uint32_t> gValidationMessages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  gValidationMessages.fetch_add(1);
  const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::fprintf(stderr, "raylab: [validation %s] %s\n", level, data->pMessage);
  return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo() {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onValidationMessage;
  return info;
}

bool envFlag(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr && std::strcmp(value, "") != 0 && std::strcmp(value, "0") != 0;
}

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

bool hasInstanceExtension(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// The extensions every capable device needs, whichever backend runs.
std::vector<const char*> requiredDeviceExtensions(bool presentation) {
  std::vector<const char*> extensions = {
      VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
      VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,  // required by VK_KHR_acceleration_structure
  };
  if (presentation) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  return extensions;
}

// The feature structs raylab enables, chained for vkGetPhysicalDeviceFeatures2 and vkCreateDevice. The structs
// of the two ray-tracing interfaces are chained only where the device has their extension: the validation
// layers refuse structs of extensions the device lacks.
struct FeatureChain {
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accelerationStructure{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rayTracingPipeline{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceShaderClockFeaturesKHR shaderClock{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CLOCK_FEATURES_KHR};

  FeatureChain(bool withRayQuery, bool withRayTracingPipeline, bool withShaderClock = false) {
    core.pNext = &vulkan12;
    vulkan12.pNext = &accelerationStructure;
    void** tail = &accelerationStructure.pNext;
    if (withRayQuery) {
      *tail = &rayQuery;
      tail = &rayQuery.pNext;
    }
    if (withRayTracingPipeline) {
      *tail = &rayTracingPipeline;
      tail = &rayTracingPipeline.pNext;
    }
    if (withShaderClock) *tail = &shaderClock;
  }
  FeatureChain(const FeatureChain&) = delete;
  FeatureChain& operator=(const FeatureChain&) = delete;
};

std::uint32_t findQueueFamily(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  // Prefer a graphics+compute family: the viewer's ImGui pass and presentation share the compute queue.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i = 0; i < count; ++i) {
      if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) continue;
      if (pass == 0 && !(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
      if (surface != VK_NULL_HANDLE) {
        VkBool32 present = VK_FALSE;
        vkGetPhysicalDeviceSurfaceSupportKHR(physical, i, surface, &present);
        if (!present) continue;
      }
      return i;
    }
  }
  return VK_QUEUE_FAMILY_IGNORED;
}

// Which of the two ray-tracing interfaces the device offers. Each feature struct is chained only when its
// extension exists: the validation layers refuse structs of extensions the device lacks.
void surveyRayTracing(VkPhysicalDevice physical, const std::vector<VkExtensionProperties>& extensions,
                      DeviceReport& report) {
  const auto has = [&](const char* name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
  };
  if (!has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) return;
  if (has(VK_KHR_RAY_QUERY_EXTENSION_NAME)) {
    VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &rayQuery};
    vkGetPhysicalDeviceFeatures2(physical, &features);
    report.rayQueries = rayQuery.rayQuery == VK_TRUE;
    if (report.rayQueries && envFlag(kHideRayQueriesVariable)) {
      report.rayQueries = false;
      report.rayQueriesHidden = true;
    }
  }
  if (has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) {
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &pipeline};
    vkGetPhysicalDeviceFeatures2(physical, &features);
    report.rayTracingPipelines = pipeline.rayTracingPipeline == VK_TRUE;
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR limits{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &limits};
    vkGetPhysicalDeviceProperties2(physical, &properties);
    report.maxRayRecursionDepth = limits.maxRayRecursionDepth;
  }
}

DeviceReport surveyOne(VkPhysicalDevice physical, std::uint32_t index, VkSurfaceKHR surface) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  subgroup.pNext = &driver;
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(physical, &properties);

  DeviceReport report;
  report.index = index;
  report.name = properties.properties.deviceName;
  report.type = properties.properties.deviceType;
  report.apiVersion = properties.properties.apiVersion;
  report.maxStorageBufferRange = properties.properties.limits.maxStorageBufferRange;
  report.driver = std::string(driver.driverName) + ", " + driver.driverInfo;

  if (report.apiVersion < VK_API_VERSION_1_2) {
    report.missing.push_back("Vulkan 1.2 (it has " + std::to_string(VK_API_VERSION_MAJOR(report.apiVersion)) + "." +
                             std::to_string(VK_API_VERSION_MINOR(report.apiVersion)) + ")");
    return report;
  }

  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data());
  surveyRayTracing(physical, extensions, report);
  for (const char* name : requiredDeviceExtensions(surface != VK_NULL_HANDLE)) {
    const bool found = std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, name) == 0;
    });
    if (!found) report.missing.push_back(name);
  }
  if (!report.missing.empty()) return report;

  FeatureChain features(false, false);
  vkGetPhysicalDeviceFeatures2(physical, &features.core);
  if (!features.vulkan12.bufferDeviceAddress) report.missing.push_back("feature bufferDeviceAddress");
  if (!features.vulkan12.scalarBlockLayout) report.missing.push_back("feature scalarBlockLayout");
  if (!features.accelerationStructure.accelerationStructure) report.missing.push_back("feature accelerationStructure");
  report.subgroupOperations = (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                              (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT) &&
                              (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT);
  const bool queries = report.rayQueries && report.subgroupOperations;
  if (!queries && !report.rayTracingPipelines) {
    report.missing.push_back(report.rayQueries ? "ray-tracing pipelines, and subgroup arithmetic and ballot in "
                                                 "compute shaders for its ray queries"
                                               : "ray queries or ray-tracing pipelines");
  }
  if (findQueueFamily(physical, surface) == VK_QUEUE_FAMILY_IGNORED) {
    report.missing.push_back(surface != VK_NULL_HANDLE ? "a compute queue that can present to the window"
                                                       : "a compute queue");
  }
  return report;
}

int typePreference(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

template <class T>
T loadDeviceFunction(VkDevice device, const char* name) {
  auto function = reinterpret_cast<T>(vkGetDeviceProcAddr(device, name));
  if (function == nullptr) throw Error(std::string("the Vulkan driver does not provide ") + name);
  return function;
}

}  // namespace

Instance createInstance(const InstanceOptions& options) {
  separateShaderCacheByDriverSettings();  // before anything loads the driver
  Instance instance;
  instance.validation = options.validation || envFlag("RAYLAB_VALIDATION");
  if (instance.validation && !hasLayer(kValidationLayer)) {
    throw Error(std::string("validation was requested but ") + kValidationLayer +
                " is not installed; run `tools/setup.sh` (package vulkan-validationlayers)");
  }
  instance.debugUtils = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  std::vector<const char*> extensions = options.extensions;
  if (instance.debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  std::vector<const char*> layers;
  if (instance.validation) layers.push_back(kValidationLayer);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "raylab";
  app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
  app.pEngineName = "raylab";
  app.apiVersion = VK_API_VERSION_1_2;

  // Chained so that messages from vkCreateInstance and vkDestroyInstance are caught too.
  VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo();
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = instance.debugUtils && instance.validation ? &messenger : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  const VkResult result = vkCreateInstance(&info, nullptr, &instance.handle);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED) {
    throw Error(std::string("no Vulkan driver was found (vkCreateInstance: ") + vkResultName(result) + "); " +
                    kSetupHint + ".",
                kExitNoDevice);
  }
  VK_CHECK(result);

  if (instance.debugUtils && instance.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance.handle, "vkCreateDebugUtilsMessengerEXT"));
    VK_CHECK(create(instance.handle, &messenger, nullptr, &instance.messenger));
  }
  return instance;
}

void destroyInstance(Instance& instance) {
  if (instance.messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance.handle, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance.handle, instance.messenger, nullptr);
  }
  if (instance.handle != VK_NULL_HANDLE) vkDestroyInstance(instance.handle, nullptr);
  instance = {};
}

std::vector<DeviceReport> surveyDevices(const Instance& instance, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, nullptr));
  std::vector<VkPhysicalDevice> physicals(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, physicals.data()));
  std::vector<DeviceReport> reports;
  for (std::uint32_t i = 0; i < count; ++i) reports.push_back(surveyOne(physicals[i], i, surface));
  return reports;
}

std::string noCapableDeviceMessage(const std::vector<DeviceReport>& reports) {
  std::string found;
  for (const DeviceReport& report : reports) {
    std::string missing;
    for (const std::string& item : report.missing) missing += (missing.empty() ? "" : ", ") + item;
    found += (found.empty() ? "" : "; ") + report.name + " (" + report.driver + ") lacks " + missing;
  }
  if (found.empty()) found = "no Vulkan device at all";
  return "raylab needs a Vulkan 1.2 device with VK_KHR_acceleration_structure and VK_KHR_ray_query or "
         "VK_KHR_ray_tracing_pipeline, but found " +
         found + "; " + kSetupHint + ".";
}

std::uint32_t chooseDevice(const std::vector<DeviceReport>& reports, std::optional<std::uint32_t> requested) {
  if (requested) {
    if (*requested >= reports.size()) {
      throw Error("--device " + std::to_string(*requested) + ": there are only " + std::to_string(reports.size()) +
                      " Vulkan devices (see `raylab devices`)",
                  kExitUsage);
    }
    const DeviceReport& report = reports[*requested];
    if (!report.capable()) throw Error(noCapableDeviceMessage({report}), kExitNoDevice);
    return *requested;
  }
  const DeviceReport* best = nullptr;
  for (const DeviceReport& report : reports) {
    if (report.capable() && (best == nullptr || typePreference(report.type) < typePreference(best->type))) {
      best = &report;
    }
  }
  if (best == nullptr) throw Error(noCapableDeviceMessage(reports), kExitNoDevice);
  return best->index;
}

Device createDevice(const Instance& instance, const DeviceReport& report, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, nullptr));
  std::vector<VkPhysicalDevice> physicals(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, physicals.data()));

  Device device;
  device.instance = instance.handle;
  device.physical = physicals.at(report.index);
  device.report = report;
  device.queueFamily = findQueueFamily(device.physical, surface);

  device.rayQueries = report.rayQueries && report.subgroupOperations;
  device.rayTracingPipelines = report.rayTracingPipelines;

  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rtProperties{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR asProperties{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  asProperties.pNext = device.rayTracingPipelines ? &rtProperties : nullptr;
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  subgroup.pNext = &asProperties;
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(device.physical, &properties);
  device.properties = properties.properties;
  device.scratchAlignment = asProperties.minAccelerationStructureScratchOffsetAlignment;
  device.maxPrimitiveCount = asProperties.maxPrimitiveCount;
  device.maxInstanceCount = asProperties.maxInstanceCount;
  device.subgroupSize = subgroup.subgroupSize;
  device.rayTracing = {rtProperties.shaderGroupHandleSize, rtProperties.shaderGroupHandleAlignment,
                       rtProperties.shaderGroupBaseAlignment, rtProperties.maxShaderGroupStride};
  vkGetPhysicalDeviceMemoryProperties(device.physical, &device.memory);

  // Which optional extension the device has: the shader clock, for --heatmap only.
  {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device.physical, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> available(count);
    vkEnumerateDeviceExtensionProperties(device.physical, nullptr, &count, available.data());
    const bool hasClock = std::any_of(available.begin(), available.end(), [](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, VK_KHR_SHADER_CLOCK_EXTENSION_NAME) == 0;
    });
    if (hasClock) {
      FeatureChain probe(false, false, true);
      vkGetPhysicalDeviceFeatures2(device.physical, &probe.core);
      device.shaderClock = probe.shaderClock.shaderDeviceClock == VK_TRUE;
    }
  }

  // Enable exactly what raylab uses, nothing the device merely offers: ray queries unless hidden, and
  // ray-tracing pipelines where there are any, so that either backend can run; the device clock where offered.
  FeatureChain features(device.rayQueries, device.rayTracingPipelines, device.shaderClock);
  features.vulkan12.bufferDeviceAddress = VK_TRUE;
  features.vulkan12.scalarBlockLayout = VK_TRUE;
  features.accelerationStructure.accelerationStructure = VK_TRUE;
  features.rayQuery.rayQuery = device.rayQueries ? VK_TRUE : VK_FALSE;
  features.rayTracingPipeline.rayTracingPipeline = device.rayTracingPipelines ? VK_TRUE : VK_FALSE;
  features.shaderClock.shaderDeviceClock = device.shaderClock ? VK_TRUE : VK_FALSE;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = device.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  std::vector<const char*> extensions = requiredDeviceExtensions(surface != VK_NULL_HANDLE);
  if (device.rayQueries) extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
  if (device.rayTracingPipelines) extensions.push_back(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  if (device.shaderClock) extensions.push_back(VK_KHR_SHADER_CLOCK_EXTENSION_NAME);
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &features.core;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(device.physical, &info, nullptr, &device.handle));
  vkGetDeviceQueue(device.handle, device.queueFamily, 0, &device.queue);

  device.ext.createAccelerationStructure =
      loadDeviceFunction<PFN_vkCreateAccelerationStructureKHR>(device.handle, "vkCreateAccelerationStructureKHR");
  device.ext.destroyAccelerationStructure =
      loadDeviceFunction<PFN_vkDestroyAccelerationStructureKHR>(device.handle, "vkDestroyAccelerationStructureKHR");
  device.ext.getAccelerationStructureBuildSizes = loadDeviceFunction<PFN_vkGetAccelerationStructureBuildSizesKHR>(
      device.handle, "vkGetAccelerationStructureBuildSizesKHR");
  device.ext.cmdBuildAccelerationStructures =
      loadDeviceFunction<PFN_vkCmdBuildAccelerationStructuresKHR>(device.handle, "vkCmdBuildAccelerationStructuresKHR");
  device.ext.getAccelerationStructureDeviceAddress =
      loadDeviceFunction<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
          device.handle, "vkGetAccelerationStructureDeviceAddressKHR");
  if (device.rayTracingPipelines) {
    device.ext.createRayTracingPipelines =
        loadDeviceFunction<PFN_vkCreateRayTracingPipelinesKHR>(device.handle, "vkCreateRayTracingPipelinesKHR");
    device.ext.getRayTracingShaderGroupHandles = loadDeviceFunction<PFN_vkGetRayTracingShaderGroupHandlesKHR>(
        device.handle, "vkGetRayTracingShaderGroupHandlesKHR");
    device.ext.cmdTraceRays = loadDeviceFunction<PFN_vkCmdTraceRaysKHR>(device.handle, "vkCmdTraceRaysKHR");
  }
  if (instance.debugUtils) {
    device.ext.setDebugUtilsObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance.handle, "vkSetDebugUtilsObjectNameEXT"));
  }

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = device.queueFamily;
  VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &device.commandPool));
  VkPipelineCacheCreateInfo cacheInfo{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  VK_CHECK(vkCreatePipelineCache(device.handle, &cacheInfo, nullptr, &device.pipelineCache));
  device.pipelines = std::make_shared<PipelineStore>();
  return device;
}

void destroyDevice(Device& device) {
  if (device.handle == VK_NULL_HANDLE) return;
  vkDeviceWaitIdle(device.handle);
  if (device.pipelines) device.pipelines->destroyAll(device.handle);
  vkDestroyPipelineCache(device.handle, device.pipelineCache, nullptr);
  vkDestroyCommandPool(device.handle, device.commandPool, nullptr);
  vkDestroyDevice(device.handle, nullptr);
  device = {};
}

std::uint32_t validationMessageCount() { return gValidationMessages.load(); }

const char* deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

}  // namespace raylab
