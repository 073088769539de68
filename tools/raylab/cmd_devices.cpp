// `raylab devices`: every Vulkan device, its driver, and whether raylab can run on it.
#include <cstdio>

#include "args.h"
#include "commands.h"
#include "util/error.h"
#include "vk/device.h"

namespace raylab {

int runDevices(int argc, char** argv) {
  ArgParser args("raylab devices", "[options]",
                 "Lists every Vulkan device with its driver, the ray-tracing interfaces it offers (ray queries,\n"
                 "ray-tracing pipelines) and whether raylab can run on it (today: ray queries, acceleration\n"
                 "structures, buffer device addresses). Use the index with --device N.");
  if (!args.parse(argc, argv)) return kExitOk;

  Instance instance = createInstance({});
  const std::vector<DeviceReport> reports = surveyDevices(instance);
  destroyInstance(instance);

  bool anyCapable = false;
  for (const DeviceReport& report : reports) {
    std::printf("%u: %s [%s]\n   driver: %s, Vulkan %u.%u.%u\n", report.index, report.name.c_str(),
                deviceTypeName(report.type), report.driver.c_str(), VK_API_VERSION_MAJOR(report.apiVersion),
                VK_API_VERSION_MINOR(report.apiVersion), VK_API_VERSION_PATCH(report.apiVersion));
    std::printf("   ray queries: %s; ray-tracing pipelines: %s", report.rayQueries ? "yes" : "no",
                report.rayTracingPipelines ? "yes" : "no");
    if (report.rayTracingPipelines) std::printf(" (max recursion depth %u)", report.maxRayRecursionDepth);
    std::printf("\n");
    if (report.capable()) {
      std::printf("   raylab: yes\n");
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

}  // namespace raylab
