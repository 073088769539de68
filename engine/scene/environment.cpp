#include "scene/environment.h"

#include <algorithm>
#include <cmath>

#include "image/image.h"
#include "util/files.h"
#include "scene/radiance_limits.h"
#include "shared/scene_records.h"
#include "util/error.h"
#include "util/log.h"

namespace raylab {

namespace {

constexpr float kPi = 3.14159265358979323846f;

}  // namespace

std::uint64_t environmentBufferBytes(std::uint32_t width, std::uint32_t height) {
  const std::uint64_t texels = std::uint64_t(width) * height;
  return sizeof(gpu::EnvironmentHeader) + (6 * texels + height) * sizeof(float);
}

Environment loadEnvironment(const std::string& path, float strength, const std::string& where,
                            const std::string& strengthWhere, std::uint64_t maxBufferBytes) {
  std::string bytes;
  try {
    bytes = readInputFile(path, kMaxEnvironmentFileBytes);
  } catch (const Error& e) {
    throw Error(where + ": environment image " + e.what());
  }
  Environment environment = decodeEnvironment(bytes, where + ": environment image " + path, maxBufferBytes);
  environment.path = path;
  checkEnvironmentStrength(environment, strength, strengthWhere.empty() ? where : strengthWhere);
  environment.strength = strength;
  return environment;
}

Environment decodeEnvironment(const std::string& bytes, const std::string& label, std::uint64_t maxBufferBytes) {
  const auto fitsTheDevice = [&](std::uint32_t width, std::uint32_t height) {
    const std::uint64_t needed = environmentBufferBytes(width, height);
    if (needed > maxBufferBytes) {
      throw Error(label + ": " + std::to_string(width) + "x" + std::to_string(height) + " needs " +
                  std::to_string(needed >> 20) + " MiB with its sampling tables, over this device's " +
                  "maxStorageBufferRange of " + std::to_string(maxBufferBytes >> 20) +
                  " MiB (docs/scenes.md, Limits): use a smaller image");
    }
  };
  const Image image = decodeExr(bytes, label, kMaxEnvironmentTexels, fitsTheDevice);
  Environment environment;
  environment.width = image.width;
  environment.height = image.height;
  environment.texels.resize(std::size_t(image.width) * image.height);
  std::uint64_t negative = 0;
  float mostNegative = 0.0f;
  double sum = 0.0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      glm::vec3 texel(image.at(x, y));
      // The bound keeps sums of texels (the sampling tables, the kernel's luminance) finite in float.
      const auto bad = [](float c) { return !(std::abs(c) <= kMaxRadiance); };
      if (bad(texel.r) || bad(texel.g) || bad(texel.b)) {
        throw Error(label + ": texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is (" +
                    std::to_string(texel.r) + ", " + std::to_string(texel.g) + ", " + std::to_string(texel.b) +
                    "); radiance must be finite and at most 1e20");
      }
      // Lossy EXR compression leaves small negative values in real HDRIs (Blender's have -4e-6): not radiance.
      if (texel.r < 0.0f || texel.g < 0.0f || texel.b < 0.0f) {
        ++negative;
        mostNegative = std::min({mostNegative, texel.r, texel.g, texel.b});
        texel = glm::max(texel, glm::vec3(0.0f));
      }
      environment.texels[std::size_t(y) * image.width + x] = texel;
      environment.brightest = std::max({environment.brightest, texel.r, texel.g, texel.b});
      sum += double(texel.r + texel.g + texel.b) / 3.0;
    }
  }
  // Compression noise (Blender's sunrise.exr: down to -0.004, under 1% of its mean) is zeroed silently;
  // anything larger is worth a word.
  const double mean = sum / double(environment.texels.size());
  if (negative > 0 && double(-mostNegative) > 0.05 * mean) {
    warn(label + ": " + std::to_string(negative) + " texels had negative values (down to " +
         std::to_string(mostNegative) + "), read as 0");
  }
  return environment;
}

glm::vec3 environmentDirection(glm::vec2 uv) {
  const float theta = uv.y * kPi;
  const float phi = 2.0f * kPi * uv.x;
  const float sinTheta = std::sin(theta);
  return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

glm::vec2 environmentUv(glm::vec3 d) {
  float u = std::atan2(d.x, -d.z) / (2.0f * kPi);
  if (u < 0.0f) u += 1.0f;
  if (u >= 1.0f) u = 0.0f;
  return {u, std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

}  // namespace raylab
