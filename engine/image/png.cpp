// Tone-mapped 8-bit sRGB PNG files through stb_image_write, and reading them back through stb_image (Debian's
// libstb).
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "image/image.h"
#include "util/error.h"
#include "util/atomic_file.h"
#include "util/files.h"

namespace raylab {

namespace {

float toneCurve(float x, ToneMap toneMap) {
  switch (toneMap) {
    case ToneMap::kClamp:
      return x;
    case ToneMap::kReinhard:
      return x / (1.0f + x);
    case ToneMap::kAces:  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve"
      return (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
  }
  return x;
}

float linearToSrgb(float x) { return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f; }

}  // namespace

std::uint8_t toDisplay(float linear, float exposure, ToneMap toneMap) {
  // NaN would be undefined behaviour in the conversion; it shows as black, never as a random byte.
  if (!(linear > 0.0f)) return 0;
  const float mapped = std::clamp(toneCurve(linear * std::exp2(exposure), toneMap), 0.0f, 1.0f);
  return static_cast<std::uint8_t>(std::lround(linearToSrgb(mapped) * 255.0f));
}

void writePngRgb8(const std::string& path, std::uint32_t width, std::uint32_t height, const std::uint8_t* rgb) {
  std::string encoded;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
  };
  // stb reports only that encoding failed (out of memory, or a size beyond its int arithmetic).
  if (stbi_write_png_to_func(append, &encoded, static_cast<int>(width), static_cast<int>(height), 3, rgb,
                             static_cast<int>(width) * 3) == 0) {
    throw Error(path + ": cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " PNG");
  }
  writeFileAtomically(path, encoded);
}

void writePng(const std::string& path, const Image& image, float exposure, ToneMap toneMap) {
  checkFinite(image, path);
  std::vector<std::uint8_t> bytes(std::size_t(image.width) * image.height * 3);
  for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
    for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = toDisplay(image.rgba[i * 4 + c], exposure, toneMap);
  }
  writePngRgb8(path, image.width, image.height, bytes.data());
}

Rgb8Image readPngRgb8(const std::string& path) {
  const std::string bytes = readInputFile(path, kMaxImageFileBytes);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) throw Error(path + ": too large a PNG file");
  const int size = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  // The header decides the size before anything is decoded: a small file may claim any size.
  if (stbi_info_from_memory(data, size, &width, &height, &channels) == 0) {
    throw Error(path + ": cannot read as PNG: " + stbi_failure_reason());
  }
  if (width < 1 || height < 1 || std::uint32_t(width) > kMaxImageSide || std::uint32_t(height) > kMaxImageSide) {
    throw Error(path + ": PNG of " + std::to_string(width) + "x" + std::to_string(height) + " pixels; raylab reads " +
                "images of at most " + std::to_string(kMaxImageSide) + " pixels a side");
  }
  unsigned char* pixels = stbi_load_from_memory(data, size, &width, &height, &channels, 3);
  if (pixels == nullptr) throw Error(path + ": cannot read as PNG: " + stbi_failure_reason());
  Rgb8Image image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.rgb.assign(pixels, pixels + std::size_t(width) * height * 3);
  stbi_image_free(pixels);
  return image;
}

}  // namespace raylab
