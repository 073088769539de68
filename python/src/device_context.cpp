#include "device_context.h"

#include <algorithm>
#include <map>

namespace raylab::python {

DeviceContext::DeviceContext(std::optional<std::uint32_t> index) : session(index, true) {}

DeviceContext::~DeviceContext() {
  if (evaluator) destroyBrdfEvaluator(session.device, *evaluator);
  if (sampler) destroyBrdfSampler(session.device, *sampler);
}

namespace {

// The kernel, recreated larger when a batch outgrows it (at least 1024 items, so small calls share one).
template <class Kernel>
Kernel& grown(const Device& device, std::optional<Kernel>& kernel, std::uint32_t needed,
              Kernel (*create)(const Device&, std::uint32_t)) {
  if (kernel && kernel->capacity < needed) {
    destroyBatchKernel(device, *kernel);
    kernel.reset();
  }
  if (!kernel) kernel = create(device, std::max<std::uint32_t>(needed, 1024));
  return *kernel;
}

}  // namespace

BrdfEvaluator& DeviceContext::evaluatorFor(std::uint32_t cases) {
  return grown(session.device, evaluator, cases, &createBrdfEvaluator);
}

BrdfSampler& DeviceContext::samplerFor(std::uint32_t samples) {
  return grown(session.device, sampler, samples, &createBrdfSampler);
}

namespace {

std::mutex contextsMutex;
// Kept for the process once made (creating a Vulkan device takes a while), until releaseDeviceContexts.
std::map<std::int64_t, std::shared_ptr<DeviceContext>> contexts;

}  // namespace

std::shared_ptr<DeviceContext> deviceContext(std::optional<std::uint32_t> index) {
  const std::lock_guard<std::mutex> lock(contextsMutex);
  std::shared_ptr<DeviceContext>& context = contexts[index ? std::int64_t(*index) : -1];
  if (!context) context = std::make_shared<DeviceContext>(index);
  return context;
}

void releaseDeviceContexts() {
  const std::lock_guard<std::mutex> lock(contextsMutex);
  contexts.clear();
}

}  // namespace raylab::python
