#include "brdf/device_evaluator.h"

#include <string>

#include "shared/bindings.h"
#include "util/error.h"
#include "util/timer.h"
#include "vk/commands.h"

namespace raylab {

namespace {

constexpr std::uint32_t kWorkgroupSize = 64;  // local_size_x of brdf_eval.comp and brdf_sample.comp

std::uint32_t workgroups(std::uint32_t count) { return (count + kWorkgroupSize - 1) / kWorkgroupSize; }

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
  evaluator.setLayout = createDescriptorSetLayout(device, bindings, "brdf eval set layout");
  evaluator.pipelineLayout =
      createPipelineLayout(device, evaluator.setLayout, sizeof(std::uint32_t), "brdf eval pipeline layout");
  evaluator.pipeline = createComputePipeline(device, evaluator.pipelineLayout, "brdf_eval.comp");
  evaluator.cases = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfEvalCase),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 MemoryUse::kDevice, "brdf eval cases");
  evaluator.values = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfEvalValue),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  MemoryUse::kDevice, "brdf eval values");
  evaluator.descriptors = allocateDescriptorSet(device, evaluator.setLayout, bindings, "brdf eval set");
  writeStorageBuffer(device, evaluator.descriptors.set, gpu::kBindingBrdfCases, evaluator.cases.handle);
  writeStorageBuffer(device, evaluator.descriptors.set, gpu::kBindingBrdfValues, evaluator.values.handle);
  return evaluator;
}

void destroyBrdfEvaluator(const Device& device, BrdfEvaluator& evaluator) {
  destroyBuffer(device, evaluator.values);
  destroyBuffer(device, evaluator.cases);
  destroyDescriptorSet(device, evaluator.descriptors);
  if (evaluator.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(device.handle, evaluator.pipeline, nullptr);
  if (evaluator.pipelineLayout != VK_NULL_HANDLE) vkDestroyPipelineLayout(device.handle, evaluator.pipelineLayout, nullptr);
  if (evaluator.setLayout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device.handle, evaluator.setLayout, nullptr);
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
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, evaluator.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, evaluator.pipelineLayout, 0, 1,
                            &evaluator.descriptors.set, 0, nullptr);
    vkCmdPushConstants(cmd, evaluator.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof count, &count);
    vkCmdDispatch(cmd, workgroups(count), 1, 1);
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
  sampler.setLayout = createDescriptorSetLayout(device, bindings, "brdf sample set layout");
  sampler.pipelineLayout =
      createPipelineLayout(device, sampler.setLayout, sizeof(gpu::BrdfSampleParams), "brdf sample pipeline layout");
  sampler.pipeline = createComputePipeline(device, sampler.pipelineLayout, "brdf_sample.comp");
  sampler.uniforms = createBuffer(device, VkDeviceSize(capacity) * sizeof(glm::vec3),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryUse::kDevice, "brdf sample uniforms");
  sampler.samples = createBuffer(device, VkDeviceSize(capacity) * sizeof(gpu::BrdfSampleValue),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                 MemoryUse::kDevice, "brdf samples");
  sampler.descriptors = allocateDescriptorSet(device, sampler.setLayout, bindings, "brdf sample set");
  writeStorageBuffer(device, sampler.descriptors.set, gpu::kBindingBrdfUniforms, sampler.uniforms.handle);
  writeStorageBuffer(device, sampler.descriptors.set, gpu::kBindingBrdfSamples, sampler.samples.handle);
  return sampler;
}

void destroyBrdfSampler(const Device& device, BrdfSampler& sampler) {
  destroyBuffer(device, sampler.samples);
  destroyBuffer(device, sampler.uniforms);
  destroyDescriptorSet(device, sampler.descriptors);
  if (sampler.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(device.handle, sampler.pipeline, nullptr);
  if (sampler.pipelineLayout != VK_NULL_HANDLE) vkDestroyPipelineLayout(device.handle, sampler.pipelineLayout, nullptr);
  if (sampler.setLayout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device.handle, sampler.setLayout, nullptr);
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
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sampler.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sampler.pipelineLayout, 0, 1,
                            &sampler.descriptors.set, 0, nullptr);
    vkCmdPushConstants(cmd, sampler.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params, &params);
    vkCmdDispatch(cmd, workgroups(params.count), 1, 1);
    computeBarrier(cmd);
  });
  downloadBuffer(device, sampler.samples, samples.data(), samples.size() * sizeof(gpu::BrdfSampleValue));
  return samples;
}

}  // namespace raylab
