// The tables that importance-sample an environment image (Pharr, Jakob and Humphreys, PBR 4th ed., 12.5.2:
// a piecewise-constant 2D distribution): a density f per texel, the cdf along each row and the cdf over rows.
// f is the luminance averaged over the texel's cell under bilinear reconstruction, times sin(theta) at the
// cell's centre, so a direction whose bilinear radiance is > 0 always has density > 0 (light sampling alone
// stays unbiased) and rows near the poles, which cover little solid angle, are sampled less.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/environment.h"

namespace raylab {

struct EnvironmentTables {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> f;            // per texel, rows from the top
  std::vector<float> rowCdf;       // per texel: inclusive, the last of each row exactly 1 (or 0 for a black row)
  std::vector<float> marginalCdf;  // per row: inclusive, the last exactly 1
  float fMean = 0.0f;              // 0: a black image, nothing to sample
};

EnvironmentTables buildEnvironmentTables(const Environment& environment);

// The density per unit solid angle with which the kernel's environmentLightSample picks image-frame direction d.
double environmentPdf(const EnvironmentTables& tables, glm::vec3 d);

// The bilinear radiance of image-frame direction d (strength 1), as the kernel's environmentRadiance.
glm::vec3 environmentLookup(const Environment& environment, glm::vec3 d);

// EnvironmentHeader and the data the kernel reads (shaders/shared/scene_records.h), as floats; `light` is the
// LightRecord that samples the image (gpu::kNoLight: none).
std::vector<float> packEnvironment(const Environment& environment, const EnvironmentTables& tables,
                                   std::uint32_t light);

}  // namespace raylab
