// `raylab devices`: every Vulkan device, its driver, the ray-tracing interfaces it offers, and whether raylab
// can run on it (with either of its two backends).
#include <cstdio>

#include "command_line/cli.h"
#include "commands.h"
#include "util/error.h"
#include "vk/device.h"

namespace raylab {

namespace {

int listDevices() {

  Instance instance = createInstance({});
  const std::vector<DeviceReport> reports = surveyDevices(instance);
  destroyInstance(instance);

  bool anyCapable = false;
  for (const DeviceReport& report : reports) {
    std::printf("%u: %s [%s]\n   driver: %s, Vulkan %u.%u.%u\n", report.index, report.name.c_str(),
                deviceTypeName(report.type), report.driver.c_str(), VK_API_VERSION_MAJOR(report.apiVersion),
                VK_API_VERSION_MINOR(report.apiVersion), VK_API_VERSION_PATCH(report.apiVersion));
    std::printf("   ray queries: %s; ray-tracing pipelines: %s",
                report.rayQueries ? "yes" : report.rayQueriesHidden ? "hidden (RAYLAB_HIDE_RAY_QUERIES)" : "no",
                report.rayTracingPipelines ? "yes" : "no");
    if (report.rayTracingPipelines) std::printf(" (max recursion depth %u)", report.maxRayRecursionDepth);
    std::printf("\n");
    if (report.capable()) {
      std::string backends = report.queryBackend() ? "query" : "";
      if (report.pipelineBackend()) backends += backends.empty() ? "pipeline" : ", pipeline";
      std::printf("   raylab: yes (backends: %s; auto: %s)\n", backends.c_str(),
                  report.queryBackend() ? "query" : "pipeline");
      anyCapable = true;
    } else {
      std::string missing;
      for (const std::string& item : report.missing) missing += (missing.empty() ? "" : ", ") + item;
      std::printf("   raylab: no, it lacks %s\n", missing.c_str());
    }
  }
  if (!anyCapable) throw Error(noCapableDeviceMessage(reports), kExitNoDevice);
  return kExitOk;
}

}  // namespace

void addDevicesCommand(CLI::App& raylab) {
  addCommand(raylab, "devices",
             "list Vulkan devices and whether raylab can use them\n"
             "Lists every Vulkan device with its driver, the ray-tracing interfaces it offers (ray queries, "
             "ray-tracing pipelines), and whether raylab can run on it: acceleration structures, buffer device "
             "addresses, and ray queries (--backend query) or ray-tracing pipelines (--backend pipeline). Use the "
             "index with --device N. RAYLAB_HIDE_RAY_QUERIES=1 hides ray queries, as a device with pipelines only "
             "would show them.",
             listDevices);
}

}  // namespace raylab
