#include "brdf_eval/albedo_estimate.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "reference/albedo.h"
#include "reference/models.h"

namespace raylab {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// Uniform floats in [0, 1) with 24 random bits, exactly representable in the float32 the device reads.
std::vector<glm::vec3> uniforms(std::uint64_t seed, std::size_t count) {
  std::mt19937_64 rng(seed);
  const auto next = [&] { return static_cast<float>(rng() >> 40) * 0x1p-24f; };
  std::vector<glm::vec3> u(count);
  for (glm::vec3& v : u) v = glm::vec3(next(), next(), next());
  return u;
}

}  // namespace

AlbedoEstimate albedoByCubature(const gpu::MaterialRecord& material, double thetaDegrees, double phiDegrees,
                                double relTolerance, int maxRegions) {
  reference::AlbedoOptions options;
  options.relTolerance = relTolerance;
  options.maxRegions = maxRegions;
  const glm::dvec3 wo = reference::directionFromAngles(thetaDegrees * kDegree, phiDegrees * kDegree);
  const reference::Albedo albedo = reference::directionalAlbedo(reference::fromRecord(material), wo, options);
  return {thetaDegrees, albedo.value, albedo.errorEstimate, albedo.evaluations, albedo.converged};
}

AlbedoEstimate albedoBySampling(const Device& device, BrdfSampler& sampler, const gpu::MaterialRecord& material,
                                double thetaDegrees, double phiDegrees, std::uint32_t samples, std::uint64_t seed) {
  const glm::vec3 wo(reference::directionFromAngles(thetaDegrees * kDegree, phiDegrees * kDegree));
  const std::vector<gpu::BrdfSampleValue> draws = drawBrdfSamples(device, sampler, material, wo, uniforms(seed, samples));
  // A two-sided model (rough glass) counts what it transmits as the cubature does: a direction inside weighs
  // eta^2, which by generalised reciprocity makes the sum the fraction of the light arriving from wo (each channel
  // its own index where the material disperses; 1 through a thin wall, which light passes without bending).
  const std::optional<glm::dvec3> etas = reference::transmissionEtas(reference::fromRecord(material));
  glm::dvec3 sum(0.0), sumSquares(0.0);
  for (const gpu::BrdfSampleValue& draw : draws) {
    if (!(draw.pdf > 0.0f)) continue;
    const glm::dvec3 inside = etas && draw.wi.z < 0.0f ? *etas * *etas : glm::dvec3(1.0);
    const glm::dvec3 weight = glm::dvec3(draw.f) * inside * (std::abs(double(draw.wi.z)) / double(draw.pdf));
    sum += weight;
    sumSquares += weight * weight;
  }
  const double n = double(samples);
  const glm::dvec3 mean = sum / n;
  const glm::dvec3 variance = glm::max(sumSquares / n - mean * mean, glm::dvec3(0.0)) * (n / std::max(n - 1.0, 1.0));
  const double error = std::sqrt(std::max({variance.x, variance.y, variance.z}) / n);
  return {thetaDegrees, mean, error, static_cast<long long>(samples), true};
}

}  // namespace raylab
