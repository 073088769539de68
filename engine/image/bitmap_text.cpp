#include "image/bitmap_text.h"

// stb_easy_font defines every function static, and this file does not use them all.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>

#include "image/image.h"

namespace raylab {

namespace {

constexpr int kLineHeight = 12;  // stb_easy_font's own line advance

// The printable copy stb_easy_font needs: a mutable C string of characters it has glyphs for (32 to 126).
std::string printable(std::string_view text) {
  std::string copy(text);
  for (char& c : copy) {
    if (c < 32 || c > 126) c = '?';
  }
  return copy;
}

}  // namespace

int textWidth(std::string_view text, int scale) {
  std::string copy = printable(text);
  return stb_easy_font_width(copy.data()) * scale;
}

int textLineHeight(int scale) { return kLineHeight * scale; }

void drawText(Rgb8Image& image, int x, int y, std::string_view text, int scale, std::array<std::uint8_t, 3> colour,
              int clipLeft, int clipRight) {
  std::string copy = printable(text);
  // stb_easy_font's estimate is about 270 bytes a character; 64 bytes (one quad) a segment, at most 40 each.
  std::vector<char> quads(copy.size() * 40 * 64 + 64);
  const int count = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, quads.data(), int(quads.size()));
  const int left = std::max(clipLeft, 0), right = std::min(clipRight, int(image.width));
  for (int q = 0; q < count; ++q) {
    // Four vertices of 16 bytes (x, y, z, colour); the first and third are opposite corners, on whole units.
    float corner0[2], corner2[2];
    std::copy_n(reinterpret_cast<const float*>(quads.data() + q * 64), 2, corner0);
    std::copy_n(reinterpret_cast<const float*>(quads.data() + q * 64 + 32), 2, corner2);
    const int x0 = std::max(x + int(corner0[0]) * scale, left);
    const int x1 = std::min(x + int(corner2[0]) * scale, right);
    const int y0 = std::max(y + int(corner0[1]) * scale, 0);
    const int y1 = std::min(y + int(corner2[1]) * scale, int(image.height));
    for (int py = y0; py < y1; ++py) {
      for (int px = x0; px < x1; ++px) {
        std::copy(colour.begin(), colour.end(), &image.rgb[(std::size_t(py) * image.width + px) * 3]);
      }
    }
  }
}

void writePng(const std::string& path, const Rgb8Image& image) {
  writePngRgb8(path, image.width, image.height, image.rgb.data());
}

}  // namespace raylab
