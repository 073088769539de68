// The Vulkan instance and device a command runs on, released in reverse order when it goes out of scope.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/backend.h"
#include "vk/device.h"

namespace raylab {

struct GpuSession {
  Instance instance;
  Device device;

  // Picks --device N or the best capable device; throws Error(kExitNoDevice) when none can run raylab.
  explicit GpuSession(std::optional<std::uint32_t> deviceIndex, bool quiet = false);
  ~GpuSession();
  GpuSession(const GpuSession&) = delete;
  GpuSession& operator=(const GpuSession&) = delete;
};

// The maxStorageBufferRange of the device a session would pick (--device N or the best capable), from a survey
// alone: scenes are loaded before the device is made, and their environment images are checked against it.
// Throws Error(kExitNoDevice) when no device can run raylab.
std::uint64_t deviceBufferLimit(std::optional<std::uint32_t> deviceIndex);

// The benchmarks' --backend (cli.h): `all` is every backend the device offers, to compare them in one run.
std::vector<Backend> backendsToCompare(const Device& device, const std::string& choice);

}  // namespace raylab
