#include "device_context.h"

#include <map>

namespace raylab::python {

DeviceContext::DeviceContext(std::optional<std::uint32_t> index) : session(index, true) {}

DeviceContext::~DeviceContext() {
  if (evaluator) destroyBrdfEvaluator(session.device, *evaluator);
  if (sampler) destroyBrdfSampler(session.device, *sampler);
}

BrdfEvaluator& DeviceContext::evaluatorFor(std::uint32_t cases) {
  if (evaluator && evaluator->capacity < cases) {
    destroyBrdfEvaluator(session.device, *evaluator);
    evaluator.reset();
  }
  if (!evaluator) evaluator = createBrdfEvaluator(session.device, std::max<std::uint32_t>(cases, 1024));
  return *evaluator;
}

BrdfSampler& DeviceContext::samplerFor(std::uint32_t samples) {
  if (sampler && sampler->capacity < samples) {
    destroyBrdfSampler(session.device, *sampler);
    sampler.reset();
  }
  if (!sampler) sampler = createBrdfSampler(session.device, std::max<std::uint32_t>(samples, 1024));
  return *sampler;
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
