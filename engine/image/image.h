// A linear RGBA float image, top row first, and its files: OpenEXR (linear, float32) and PNG (tone-mapped
// sRGB, 8-bit).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

// The luminance of a linear RGB colour (Rec. 709 / sRGB primaries, as every image here is).
inline float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The largest image side raylab renders, shows or reads as a texture; a render's pixel count is further bounded by
// the device (maxImagePixels in render/renderer.h).
inline constexpr std::uint32_t kMaxImageSide = 16384;

struct Image {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> rgba;  // 4 floats per pixel

  Image() = default;
  Image(std::uint32_t w, std::uint32_t h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0.0f) {}
  glm::vec4 at(std::uint32_t x, std::uint32_t y) const {
    const float* p = &rgba[(std::size_t(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  void set(std::uint32_t x, std::uint32_t y, glm::vec4 value) {
    float* p = &rgba[(std::size_t(y) * width + x) * 4];
    p[0] = value.r, p[1] = value.g, p[2] = value.b, p[3] = value.a;
  }
};

// The first-hit albedo and normal images of a render (render/renderer.h, readAuxiliaryImages), noise-free enough that
// a denoiser uses them as they are (denoise/denoise.h).
struct AuxiliaryImages {
  Image albedo;
  Image normal;
};

// The exposure a tone-mapped image may be given, in stops either way (the command line, the viewer, Python).
inline constexpr float kMaxExposureStops = 20.0f;

enum class ToneMap {
  kClamp,     // exposure, then clip to [0, 1]: linear below white, which suits BRDF comparisons
  kReinhard,  // x / (1 + x) on each channel
  kAces,      // Narkowicz's fit of the ACES filmic curve
};

// Throws Error naming `path`, the first non-finite pixel and how many there are: no writer writes NaN or infinity,
// which would poison every tool that reads the file (a mean, a difference, a tone curve).
void checkFinite(const Image& image, const std::string& path);

// Every writer writes atomically (util/atomic_file.h): a failure keeps the old file. Parent directories are
// created. Errors name the file.
void writeExr(const std::string& path, const Image& image);
Image readExr(const std::string& path);
// An OpenEXR file held in memory; `label` (its path) starts every error. An image of more than `maxPixels`
// pixels is refused from its header, before anything is allocated.
// `checkSize(width, height)`, when given, is called with the display window's size before anything is decoded
// (it throws to refuse).
Image decodeExr(const std::string& bytes, const std::string& label, std::uint64_t maxPixels = std::uint64_t(1) << 31,
                const std::function<void(std::uint32_t, std::uint32_t)>& checkSize = {});
// `exposure` in stops: values are scaled by 2^exposure before the tone curve and the sRGB transfer function.
void writePng(const std::string& path, const Image& image, float exposure, ToneMap toneMap);

// The one PNG encoder: 8-bit RGB rows, top first.
void writePngRgb8(const std::string& path, std::uint32_t width, std::uint32_t height, const std::uint8_t* rgb);

// A display-referred image: 8-bit sRGB, RGB, top row first.
struct Rgb8Image {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel
};
// An 8-bit PNG read back (any PNG: grey and alpha are converted to RGB). Errors name the file.
Rgb8Image readPngRgb8(const std::string& path);

// The 8-bit sRGB value of a linear value after exposure and tone mapping.
std::uint8_t toDisplay(float linear, float exposure, ToneMap toneMap);

}  // namespace raylab
