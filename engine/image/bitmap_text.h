// Labels for figures: stb_easy_font's segment font, rasterised at an integer scale into 8-bit sRGB pixels.
// The font is made of axis-aligned one-unit segments, so at an integer scale every pixel is fully inside or
// outside a glyph and no anti-aliasing is needed. ASCII only; other bytes show as '?'.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"  // Rgb8Image

namespace raylab {

// Size of one line of text in pixels at `scale`: the advance of every character, and the line height
// (capitals, descenders and the gap to the next line).
int textWidth(std::string_view text, int scale);
int textLineHeight(int scale);

// Draws `text` with its top-left corner at (x, y), clipped to the columns [clipLeft, clipRight) and to the
// image.
void drawText(Rgb8Image& image, int x, int y, std::string_view text, int scale, std::array<std::uint8_t, 3> colour,
              int clipLeft, int clipRight);

// Writes a PNG (parent directories are created). Errors name the file.
void writePng(const std::string& path, const Rgb8Image& image);

}  // namespace raylab
