// The per-pixel cost map of `raylab render --heatmap`: clock ticks per sample as a false-colour PNG with a colour
// bar and its scale, and the raw values as an OpenEXR image beside it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "image/bitmap_text.h"

namespace raylab {

// The false-colour ramp of cost maps and of the viewer's difference view: dark blue (0) through blue, green and
// yellow to white (1 and above), 8-bit sRGB.
std::array<std::uint8_t, 3> falseColour(double t);

struct CostMap {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<float> ticks;  // device clock ticks per sample, per pixel, top row first
};

// Statistics the legend prints: the median cost and the scale's top. Both are ranks, not means: a lavapipe thread
// the OS preempts mid-dispatch leaves pixels with huge clock readings, which would dominate a mean and wash out the
// map. The kernel keeps each pixel's cheapest dispatch, which removes them when a render has several dispatches;
// the top is the 99th percentile.
struct CostScale {
  double median = 0.0;
  double top = 0.0;
};
CostScale costScale(const CostMap& map);

// The map in false colour (dark blue: cheap, through green and yellow to white: the scale's top and above),
// with a colour bar below it labelled in multiples of the median cost, and the median in ticks.
Rgb8Image costMapImage(const CostMap& map, const std::string& title);

// Writes the PNG at `pngPath` and the raw ticks (in every channel) as OpenEXR beside it (same name, .exr).
void writeCostMap(const std::string& pngPath, const CostMap& map, const std::string& title);

}  // namespace raylab
