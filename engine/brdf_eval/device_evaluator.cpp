#include "brdf_eval/device_evaluator.h"

#include <algorithm>
#include <string>

#include "brdf_tables/brdf_tables.h"
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

struct BatchLayout {
  const char* shader;
  std::uint32_t pushBytes;
  std::uint32_t inputBinding;
  VkDeviceSize inputStride;
  const char* inputName;
  std::uint32_t outputBinding;
  VkDeviceSize outputStride;
  const char* outputName;
};

BatchKernel createBatchKernel(const Device& device, const BatchLayout& layout, std::uint32_t capacity) {
  BatchKernel batch;
  batch.capacity = capacity;
  const DescriptorBinding bindings[] = {{layout.inputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                        {layout.outputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                        {gpu::kBindingBrdfTables, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  batch.kernel = createComputeKernel(device, layout.shader, bindings, layout.pushBytes);
  batch.inputs = createBuffer(device, VkDeviceSize(capacity) * layout.inputStride,
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kDevice,
                              layout.inputName);
  batch.outputs = createBuffer(device, VkDeviceSize(capacity) * layout.outputStride,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               MemoryUse::kDevice, layout.outputName);
  writeStorageBuffer(device, batch.kernel.descriptors.set, layout.inputBinding, batch.inputs.handle);
  writeStorageBuffer(device, batch.kernel.descriptors.set, layout.outputBinding, batch.outputs.handle);
  batch.tables = createBrdfTables(device);
  writeStorageBuffer(device, batch.kernel.descriptors.set, gpu::kBindingBrdfTables, batch.tables.handle);
  return batch;
}

// The records as the device sees them; the tables are rebuilt when they use other measured files.
std::vector<gpu::MaterialRecord> bindMaterials(const Device& device, BatchKernel& batch,
                                               std::span<const gpu::MaterialRecord> records) {
  DeviceMaterials materials = deviceMaterials(records);
  if (updateBrdfTables(device, batch.tables, batch.measuredFiles, materials.measuredFiles)) {
    writeStorageBuffer(device, batch.kernel.descriptors.set, gpu::kBindingBrdfTables, batch.tables.handle);
  }
  return std::move(materials.records);
}

}  // namespace

void destroyBatchKernel(const Device& device, BatchKernel& batch) {
  destroyBuffer(device, batch.tables);
  destroyBuffer(device, batch.outputs);
  destroyBuffer(device, batch.inputs);
  destroyComputeKernel(device, batch.kernel);
  batch = {};
}

BrdfEvaluator createBrdfEvaluator(const Device& device, std::uint32_t capacity) {
  BrdfEvaluator evaluator;
  static_cast<BatchKernel&>(evaluator) = createBatchKernel(
      device, {"brdf_eval.comp", sizeof(std::uint32_t), gpu::kBindingBrdfCases, sizeof(gpu::BrdfEvalCase),
               "brdf eval cases", gpu::kBindingBrdfValues, sizeof(gpu::BrdfEvalValue), "brdf eval values"},
      capacity);
  return evaluator;
}

void destroyBrdfEvaluator(const Device& device, BrdfEvaluator& evaluator) { destroyBatchKernel(device, evaluator); }

std::vector<gpu::BrdfEvalValue> evaluateBrdfCases(const Device& device, BrdfEvaluator& evaluator,
                                                  std::span<const gpu::BrdfEvalCase> cases,
                                                  double* dispatchSeconds) {
  checkCapacity("evaluateBrdfCases", cases.size(), evaluator.capacity);
  const auto count = static_cast<std::uint32_t>(cases.size());
  std::vector<gpu::BrdfEvalValue> values(count);
  if (count == 0) return values;
  std::vector<gpu::MaterialRecord> records;
  for (const gpu::BrdfEvalCase& c : cases) records.push_back(c.material);
  records = bindMaterials(device, evaluator, records);
  std::vector<gpu::BrdfEvalCase> deviceCases(cases.begin(), cases.end());
  for (std::size_t i = 0; i < deviceCases.size(); ++i) deviceCases[i].material = records[i];
  uploadBuffer(device, evaluator.inputs, deviceCases.data(), cases.size_bytes());
  const Stopwatch clock;
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    recordDispatch(cmd, evaluator.kernel, &count, workgroups(count));
    computeBarrier(cmd);
  });
  if (dispatchSeconds != nullptr) *dispatchSeconds = clock.seconds();
  downloadBuffer(device, evaluator.outputs, values.data(), values.size() * sizeof(gpu::BrdfEvalValue));
  return values;
}

std::vector<gpu::BrdfEvalValue> evaluateBrdfCasesOnce(const Device& device, std::span<const gpu::BrdfEvalCase> cases,
                                                      double* dispatchSeconds) {
  // In batches of at most 2^18 cases (60 MB of them): a storage buffer may be no larger than the device's
  // maxStorageBufferRange, 128 MB on lavapipe, which the parity test's 280,000 openpbr cases exceed.
  constexpr std::size_t kBatch = std::size_t(1) << 18;
  BrdfEvaluator evaluator = createBrdfEvaluator(device, static_cast<std::uint32_t>(std::min(cases.size(), kBatch)));
  try {
    std::vector<gpu::BrdfEvalValue> values;
    values.reserve(cases.size());
    double total = 0.0;
    for (std::size_t first = 0; first < cases.size(); first += kBatch) {
      double seconds = 0.0;
      const std::vector<gpu::BrdfEvalValue> batch =
          evaluateBrdfCases(device, evaluator, cases.subspan(first, std::min(kBatch, cases.size() - first)), &seconds);
      values.insert(values.end(), batch.begin(), batch.end());
      total += seconds;
    }
    if (dispatchSeconds != nullptr) *dispatchSeconds = total;
    destroyBrdfEvaluator(device, evaluator);
    return values;
  } catch (...) {
    destroyBrdfEvaluator(device, evaluator);
    throw;
  }
}

BrdfSampler createBrdfSampler(const Device& device, std::uint32_t capacity) {
  BrdfSampler sampler;
  static_cast<BatchKernel&>(sampler) = createBatchKernel(
      device, {"brdf_sample.comp", sizeof(gpu::BrdfSampleParams), gpu::kBindingBrdfUniforms, sizeof(glm::vec3),
               "brdf sample uniforms", gpu::kBindingBrdfSamples, sizeof(gpu::BrdfSampleValue), "brdf samples"},
      capacity);
  return sampler;
}

void destroyBrdfSampler(const Device& device, BrdfSampler& sampler) { destroyBatchKernel(device, sampler); }

std::vector<gpu::BrdfSampleValue> drawBrdfSamples(const Device& device, BrdfSampler& sampler,
                                                  const gpu::MaterialRecord& material, glm::vec3 wo,
                                                  std::span<const glm::vec3> uniforms) {
  checkCapacity("drawBrdfSamples", uniforms.size(), sampler.capacity);
  gpu::BrdfSampleParams params{};
  params.material = bindMaterials(device, sampler, std::span(&material, 1)).front();
  params.wo = wo;
  params.count = static_cast<std::uint32_t>(uniforms.size());
  std::vector<gpu::BrdfSampleValue> samples(params.count);
  if (params.count == 0) return samples;
  uploadBuffer(device, sampler.inputs, uniforms.data(), uniforms.size_bytes());
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    recordDispatch(cmd, sampler.kernel, &params, workgroups(params.count));
    computeBarrier(cmd);
  });
  downloadBuffer(device, sampler.outputs, samples.data(), samples.size() * sizeof(gpu::BrdfSampleValue));
  return samples;
}

}  // namespace raylab
