// The directional albedo a(wo) = integral of f(wi, wo) cos_i dwi of one material at one outgoing angle, two ways:
// the reference's adaptive cubature (double precision), and a Monte Carlo estimate from the device's own sampler
// (bsdfSample in brdf_sample.comp), an independent cross-check of the shaders' sampling and evaluation.
// `raylab brdf albedo`, the Python module's brdf.albedo and the viewer's albedo curve use them.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "brdf_eval/device_evaluator.h"

namespace raylab {

struct AlbedoEstimate {
  double thetaDegrees = 0.0;
  glm::dvec3 value{0.0};
  double error = 0.0;          // cubature: its error estimate; sampling: one standard error (largest channel)
  long long evaluations = 0;   // cubature: calls of the model; sampling: samples drawn
  bool converged = true;       // cubature: the tolerance was reached
};

AlbedoEstimate albedoByCubature(const gpu::MaterialRecord& material, double thetaDegrees, double phiDegrees,
                                double relTolerance, int maxRegions = 20000);

// The mean of f cos_i / pdf over `samples` draws of the device's sampler with uniforms from `seed` (24-bit floats,
// exact in float32); a failed draw (pdf 0) contributes 0, which keeps it unbiased since the sampler's pdf covers
// every direction where f cos_i > 0. `sampler` must hold `samples`.
AlbedoEstimate albedoBySampling(const Device& device, BrdfSampler& sampler, const gpu::MaterialRecord& material,
                                double thetaDegrees, double phiDegrees, std::uint32_t samples, std::uint64_t seed);

}  // namespace raylab
