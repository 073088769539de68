#include "scene/texture_lookup.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

// glTF samplers' wrap modes (glTF 2.0 3.8.4.3, as OpenGL defines them) for texel index i of `size`.
long long wrapTexel(long long i, long long size, std::uint32_t mode) {
  if (mode == gpu::kWrapClamp) return std::clamp(i, 0LL, size - 1);
  if (mode == gpu::kWrapMirror) {
    const long long period = 2 * size;
    const long long j = ((i % period) + period) % period;
    return j < size ? j : period - 1 - j;
  }
  return ((i % size) + size) % size;
}

glm::dvec4 texel(const Texture& texture, long long x, long long y, bool srgb) {
  const long long wx = wrapTexel(x, texture.width, texture.wrapS);
  const long long wy = wrapTexel(y, texture.height, texture.wrapT);
  const std::size_t at = 4 * std::size_t(wy * texture.width + wx);
  glm::dvec4 value;
  for (int c = 0; c < 4; ++c) {
    value[c] = texture.rgba16.empty() ? texture.rgba[at + std::size_t(c)] / 255.0 : texture.rgba16[at + std::size_t(c)] / 65535.0;
  }
  if (srgb) {
    for (int c = 0; c < 3; ++c) value[c] = srgbToLinear(value[c]);
  }
  return value;
}

}  // namespace

double srgbToLinear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

glm::dvec2 textureUv(const gpu::TextureRef& ref, glm::dvec2 uv0, glm::dvec2 uv1) {
  const glm::dvec3 uv(ref.texCoord == 1 ? uv1 : uv0, 1.0);
  return {glm::dot(glm::dvec3(ref.row0), uv), glm::dot(glm::dvec3(ref.row1), uv)};
}

glm::dvec4 sampleTexture(const Texture& texture, glm::dvec2 uv, bool srgb) {
  if (std::isnan(uv.x) || std::isnan(uv.y)) uv = glm::dvec2(0.0);
  // Texel coordinates, bounded as the kernel bounds them: far beyond any texture's period.
  const glm::dvec2 position = glm::clamp(uv * glm::dvec2(texture.width, texture.height), -1048576.0, 1048576.0);
  if (texture.nearest) return texel(texture, std::llround(std::floor(position.x)), std::llround(std::floor(position.y)), srgb);
  const glm::dvec2 centred = position - 0.5;
  const glm::dvec2 cell = glm::floor(centred);
  const glm::dvec2 f = centred - cell;
  const long long x = std::llround(cell.x), y = std::llround(cell.y);
  const glm::dvec4 top = glm::mix(texel(texture, x, y, srgb), texel(texture, x + 1, y, srgb), f.x);
  const glm::dvec4 bottom = glm::mix(texel(texture, x, y + 1, srgb), texel(texture, x + 1, y + 1, srgb), f.x);
  return glm::mix(top, bottom, f.y);
}

}  // namespace raylab
