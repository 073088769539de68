#include "session/gpu_session.h"
#include "render/render_choices.h"

#include <cstdio>

namespace raylab {

GpuSession::GpuSession(std::optional<std::uint32_t> deviceIndex, bool quiet) {
  instance = createInstance({});
  try {
    const std::vector<DeviceReport> reports = surveyDevices(instance);
    const DeviceReport& chosen = reports[chooseDevice(reports, deviceIndex)];
    if (!quiet) std::fprintf(stderr, "raylab: device %u: %s (%s)\n", chosen.index, chosen.name.c_str(), chosen.driver.c_str());
    device = createDevice(instance, chosen);
  } catch (...) {
    destroyInstance(instance);
    throw;
  }
}

std::uint64_t deviceBufferLimit(std::optional<std::uint32_t> deviceIndex) {
  Instance probe = createInstance({});
  try {
    const std::vector<DeviceReport> reports = surveyDevices(probe);
    const std::uint64_t limit = reports[chooseDevice(reports, deviceIndex)].maxStorageBufferRange;
    destroyInstance(probe);
    return limit;
  } catch (...) {
    destroyInstance(probe);
    throw;
  }
}

std::vector<Backend> backendsToCompare(const Device& device, const std::string& choice) {
  if (choice != "all") return {chooseBackend(device, parseBackendChoice(choice, "--backend"))};
  std::vector<Backend> backends;
  if (device.rayQueries) backends.push_back(Backend::kQuery);
  if (device.rayTracingPipelines) backends.push_back(Backend::kPipeline);
  return backends;
}

GpuSession::~GpuSession() {
  destroyDevice(device);
  destroyInstance(instance);
}

}  // namespace raylab
