// The Vulkan devices of a Python process: one GpuSession per device index, made at its first use and shared by
// every Renderer and brdf call on it, with a mutex around its queue (Python threads may call in concurrently once
// the GIL is released), and the BRDF evaluator and sampler, grown to the largest batch seen.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>

#include "brdf_eval/device_evaluator.h"
#include "session/gpu_session.h"

namespace raylab::python {

struct DeviceContext {
  explicit DeviceContext(std::optional<std::uint32_t> index);
  ~DeviceContext();

  GpuSession session;
  std::mutex queue;  // held while a submission of this device runs
  std::optional<BrdfEvaluator> evaluator;
  std::optional<BrdfSampler> sampler;

  BrdfEvaluator& evaluatorFor(std::uint32_t cases);  // call with `queue` held
  BrdfSampler& samplerFor(std::uint32_t samples);    // likewise
};

// The context of device `index` (none: the best capable device), made on first use.
std::shared_ptr<DeviceContext> deviceContext(std::optional<std::uint32_t> index);
// Drops the module's references (at interpreter exit); renderers still alive keep theirs.
void releaseDeviceContexts();

}  // namespace raylab::python
