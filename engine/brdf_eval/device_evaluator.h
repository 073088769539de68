// The BRDF library on the Vulkan device: brdf_eval.comp evaluates a list of cases in one dispatch
// (`raylab brdf eval --backend gpu`, the parity tests), brdf_sample.comp draws bsdfSample (sampling tests).
#pragma once

#include <span>
#include <vector>

#include "shared/brdf_eval.h"
#include "vk/device.h"
#include "vk/compute_kernel.h"
#include "vk/resources.h"

namespace raylab {

// What both kernels are: a compute kernel over a batch of up to `capacity` items, read from `inputs` and
// written to `outputs` (one entry per item in each).
struct BatchKernel {
  ComputeKernel kernel;
  Buffer inputs;
  Buffer outputs;
  Buffer tables;  // the BRDF library's tables (brdf_tables/brdf_tables.h)
  std::vector<std::uint32_t> measuredFiles;  // in `tables`, for the last batch's materials
  std::uint32_t capacity = 0;
};
void destroyBatchKernel(const Device& device, BatchKernel& batch);

// brdf_eval.comp: inputs are BrdfEvalCase, outputs BrdfEvalValue.
struct BrdfEvaluator : BatchKernel {};

BrdfEvaluator createBrdfEvaluator(const Device& device, std::uint32_t capacity);
void destroyBrdfEvaluator(const Device& device, BrdfEvaluator& evaluator);

// Uploads the cases (at most `capacity`), evaluates them in one dispatch and downloads the values.
// `dispatchSeconds`, when given, receives the wall-clock time of the dispatch alone.
std::vector<gpu::BrdfEvalValue> evaluateBrdfCases(const Device& device, BrdfEvaluator& evaluator,
                                                  std::span<const gpu::BrdfEvalCase> cases,
                                                  double* dispatchSeconds = nullptr);

// Creates an evaluator for `cases`, evaluates them and destroys it.
std::vector<gpu::BrdfEvalValue> evaluateBrdfCasesOnce(const Device& device, std::span<const gpu::BrdfEvalCase> cases,
                                                      double* dispatchSeconds = nullptr);

// brdf_sample.comp: inputs are the uniforms u (vec3), outputs BrdfSampleValue.
struct BrdfSampler : BatchKernel {};

BrdfSampler createBrdfSampler(const Device& device, std::uint32_t capacity);
void destroyBrdfSampler(const Device& device, BrdfSampler& sampler);

// One bsdfSample(material, wo, u) per entry of `uniforms` (each in [0, 1)^3), in one dispatch; wo in the local
// frame.
std::vector<gpu::BrdfSampleValue> drawBrdfSamples(const Device& device, BrdfSampler& sampler,
                                                  const gpu::MaterialRecord& material, glm::vec3 wo,
                                                  std::span<const glm::vec3> uniforms);

}  // namespace raylab
