#include "brdf_eval/device_evaluator.h"

#include <string>

#include "shared/bindings.h"
#include "util/error.h"
#include "util/timer.h"
#include "vk/commands.h"

namespace raylab {

namespace {

std::uint32_t workgroups(std::uint32_t count) { return (count + gpu::kBrdfWorkgroupSize - 1) / gpu::kBrdfWorkgroupSize; }

void checkCapacity(const char* what, std::size_t count, std::uint32_t capacity) {
  if (count > capacity) {
    throw Error(std::string(what) + ": " + std::to_string(count) + " items exceed the capacity of " +
                std::to_string(capacity));
  }
}

}  // namespace

BrdfEvaluator createBrdfEvaluator(const Device& device, std::uint32_t capacity) {
  BrdfEvaluator evaluator;
  evaluator.capacity = capacity;
  const DescriptorBinding bindings[] = {{gpu::kBindingBrdfCases, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                        {gpu::kBindingBrdfValues, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  evaluator.kernel = createComputeKernel(device, "brdf_eval.comp", bindings, sizeof(std::uint32_t));
  evaluator.cases = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfEvalCase),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 MemoryUse::kDevice, "brdf eval cases");
  evaluator.values = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfEvalValue),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  MemoryUse::kDevice, "brdf eval values");
  writeStorageBuffer(device, evaluator.kernel.descriptors.set, gpu::kBindingBrdfCases, evaluator.cases.handle);
  writeStorageBuffer(device, evaluator.kernel.descriptors.set, gpu::kBindingBrdfValues, evaluator.values.handle);
  return evaluator;
}

void destroyBrdfEvaluator(const Device& device, BrdfEvaluator& evaluator) {
  destroyBuffer(device, evaluator.values);
  destroyBuffer(device, evaluator.cases);
  destroyComputeKernel(device, evaluator.kernel);
  evaluator = {};
}

std::vector<gpu::BrdfEvalValue> evaluateBrdfCases(const Device& device, BrdfEvaluator& evaluator,
                                                  std::span<const gpu::BrdfEvalCase> cases,
                                                  double* dispatchSeconds) {
  checkCapacity("evaluateBrdfCases", cases.size(), evaluator.capacity);
  const auto count = static_cast<std::uint32_t>(cases.size());
  std::vector<gpu::BrdfEvalValue> values(count);
  if (count == 0) return values;
  uploadBuffer(device, evaluator.cases, cases.data(), cases.size_bytes());
  const Stopwatch clock;
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    recordDispatch(cmd, evaluator.kernel, &count, workgroups(count));
    computeBarrier(cmd);
  });
  if (dispatchSeconds != nullptr) *dispatchSeconds = clock.seconds();
  downloadBuffer(device, evaluator.values, values.data(), values.size() * sizeof(gpu::BrdfEvalValue));
  return values;
}

std::vector<gpu::BrdfEvalValue> evaluateBrdfCasesOnce(const Device& device, std::span<const gpu::BrdfEvalCase> cases,
                                                      double* dispatchSeconds) {
  BrdfEvaluator evaluator = createBrdfEvaluator(device, static_cast<std::uint32_t>(cases.size()));
  try {
    std::vector<gpu::BrdfEvalValue> values = evaluateBrdfCases(device, evaluator, cases, dispatchSeconds);
    destroyBrdfEvaluator(device, evaluator);
    return values;
  } catch (...) {
    destroyBrdfEvaluator(device, evaluator);
    throw;
  }
}

BrdfSampler createBrdfSampler(const Device& device, std::uint32_t capacity) {
  BrdfSampler sampler;
  sampler.capacity = capacity;
  const DescriptorBinding bindings[] = {{gpu::kBindingBrdfUniforms, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                        {gpu::kBindingBrdfSamples, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  sampler.kernel = createComputeKernel(device, "brdf_sample.comp", bindings, sizeof(gpu::BrdfSampleParams));
  sampler.uniforms = createBuffer(device, VkDeviceSize(capacity) * sizeof(glm::vec3),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryUse::kDevice, "brdf sample uniforms");
  sampler.samples = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfSampleValue),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                 MemoryUse::kDevice, "brdf samples");
  writeStorageBuffer(device, sampler.kernel.descriptors.set, gpu::kBindingBrdfUniforms, sampler.uniforms.handle);
  writeStorageBuffer(device, sampler.kernel.descriptors.set, gpu::kBindingBrdfSamples, sampler.samples.handle);
  return sampler;
}

void destroyBrdfSampler(const Device& device, BrdfSampler& sampler) {
  destroyBuffer(device, sampler.samples);
  destroyBuffer(device, sampler.uniforms);
  destroyComputeKernel(device, sampler.kernel);
  sampler = {};
}

std::vector<gpu::BrdfSampleValue> drawBrdfSamples(const Device& device, BrdfSampler& sampler,
                                                  const gpu::MaterialRecord& material, glm::vec3 wo,
                                                  std::span<const glm::vec3> uniforms) {
  checkCapacity("drawBrdfSamples", uniforms.size(), sampler.capacity);
  gpu::BrdfSampleParams params{};
  params.material = material;
  params.wo = wo;
  params.count = static_cast<std::uint32_t>(uniforms.size());
  std::vector<gpu::BrdfSampleValue> samples(params.count);
  if (params.count == 0) return samples;
  uploadBuffer(device, sampler.uniforms, uniforms.data(), uniforms.size_bytes());
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    recordDispatch(cmd, sampler.kernel, &params, workgroups(params.count));
    computeBarrier(cmd);
  });
  downloadBuffer(device, sampler.samples, samples.data(), samples.size() * sizeof(gpu::BrdfSampleValue));
  return samples;
}

}  // namespace raylab
