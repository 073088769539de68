#include "scene/environment_tables.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "image/image.h"
#include "shared/scene_records.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;


// Texel (x, y) of the image with its addressing: wrapped around in u, clamped at the poles (as the kernel's
// environmentTexel).
glm::vec3 texelAt(const Environment& environment, std::int64_t x, std::int64_t y) {
  const std::int64_t w = environment.width, h = environment.height;
  x = (x % w + w) % w;
  y = std::clamp<std::int64_t>(y, 0, h - 1);
  return environment.texels[std::size_t(y * w + x)];
}

// Inclusive cdf of `values` into `cdf`, normalised so that the last entry is exactly 1; all zeros if the sum is.
double inclusiveCdf(const float* values, std::size_t count, float* cdf) {
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    sum += values[i];
    cdf[i] = float(sum);
  }
  for (std::size_t i = 0; i < count; ++i) cdf[i] = sum > 0.0 ? float(double(cdf[i]) / sum) : 0.0f;
  if (sum > 0.0) cdf[count - 1] = 1.0f;
  return sum;
}

}  // namespace

EnvironmentTables buildEnvironmentTables(const Environment& environment) {
  EnvironmentTables tables;
  const std::uint32_t w = environment.width, h = environment.height;
  tables.width = w;
  tables.height = h;
  if (!environment.hasImage()) return tables;
  // The mean of the bilinear reconstruction over one texel's cell is a separable [1, 6, 1] / 8 filter of the
  // texels around it.
  constexpr double kWeights[3] = {1.0 / 8.0, 6.0 / 8.0, 1.0 / 8.0};
  tables.f.resize(std::size_t(w) * h);
  std::vector<float> rowSums(h);
  tables.rowCdf.resize(std::size_t(w) * h);
  for (std::uint32_t y = 0; y < h; ++y) {
    const double sinTheta = std::sin(kPi * (y + 0.5) / h);
    for (std::uint32_t x = 0; x < w; ++x) {
      double mean = 0.0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::vec3 texel = texelAt(environment, std::int64_t(x) + dx, std::int64_t(y) + dy);
          mean += kWeights[dy + 1] * kWeights[dx + 1] * double(luminance(texel));
        }
      }
      tables.f[std::size_t(y) * w + x] = float(mean * sinTheta);
    }
    rowSums[y] = float(inclusiveCdf(&tables.f[std::size_t(y) * w], w, &tables.rowCdf[std::size_t(y) * w]));
  }
  tables.marginalCdf.resize(h);
  const double total = inclusiveCdf(rowSums.data(), h, tables.marginalCdf.data());
  tables.fMean = float(total / (double(w) * h));
  return tables;
}

double environmentPdf(const EnvironmentTables& tables, glm::vec3 d) {
  if (!(tables.fMean > 0.0f)) return 0.0;
  const glm::vec2 uv = environmentUv(d);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - double(d.y) * d.y));
  if (!(sinTheta > 0.0)) return 0.0;
  const std::uint32_t x = std::min(std::uint32_t(uv.x * tables.width), tables.width - 1);
  const std::uint32_t y = std::min(std::uint32_t(uv.y * tables.height), tables.height - 1);
  return double(tables.f[std::size_t(y) * tables.width + x]) / tables.fMean / (2.0 * kPi * kPi * sinTheta);
}

glm::vec3 environmentLookup(const Environment& environment, glm::vec3 d) {
  if (!environment.hasImage()) return glm::vec3(0.0f);
  const glm::vec2 uv = environmentUv(d);
  const std::int64_t w = environment.width, h = environment.height;
  const float fx = uv.x * float(w) - 0.5f, fy = uv.y * float(h) - 0.5f;
  const std::int64_t x0 = std::int64_t(std::floor(fx)), y0 = std::int64_t(std::floor(fy));
  const float tx = fx - float(x0), ty = fy - float(y0);
  const auto texel = [&](std::int64_t x, std::int64_t y) { return texelAt(environment, x, y); };
  return (1.0f - ty) * ((1.0f - tx) * texel(x0, y0) + tx * texel(x0 + 1, y0)) +
         ty * ((1.0f - tx) * texel(x0, y0 + 1) + tx * texel(x0 + 1, y0 + 1));
}

std::vector<float> packEnvironment(const Environment& environment, const EnvironmentTables& tables, std::uint32_t light) {
  constexpr std::size_t kHeaderFloats = sizeof(gpu::EnvironmentHeader) / sizeof(float);
  gpu::EnvironmentHeader header{};
  header.light = light;
  std::vector<float> data(kHeaderFloats);
  if (environment.hasImage()) {
    header.width = tables.width;
    header.height = tables.height;
    header.fMean = tables.fMean;
    for (const glm::vec3& texel : environment.texels) data.insert(data.end(), {texel.r, texel.g, texel.b});
    data.insert(data.end(), tables.f.begin(), tables.f.end());
    data.insert(data.end(), tables.rowCdf.begin(), tables.rowCdf.end());
    data.insert(data.end(), tables.marginalCdf.begin(), tables.marginalCdf.end());
  } else {
    data.push_back(0.0f);  // a buffer may not be empty
  }
  std::memcpy(data.data(), &header, sizeof(header));
  return data;
}

}  // namespace raylab
