#include "image/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "image/image.h"

namespace raylab {

// A perceptually ordered ramp: black-blue, blue, green, yellow, white (piecewise linear in sRGB); display.comp's
// falseColour holds the same stops.
std::array<std::uint8_t, 3> falseColour(double t) {
  static constexpr std::array<std::array<double, 3>, 5> kStops = {
      {{0.05, 0.03, 0.20}, {0.10, 0.30, 0.85}, {0.10, 0.75, 0.35}, {0.95, 0.85, 0.10}, {1.00, 1.00, 1.00}}};
  t = std::clamp(t, 0.0, 1.0) * double(kStops.size() - 1);
  const std::size_t i = std::min<std::size_t>(std::size_t(t), kStops.size() - 2);
  const double f = t - double(i);
  std::array<std::uint8_t, 3> rgb{};
  for (int c = 0; c < 3; ++c) {
    rgb[c] = std::uint8_t(std::lround(255.0 * ((1.0 - f) * kStops[i][c] + f * kStops[i + 1][c])));
  }
  return rgb;
}

namespace {

constexpr int kTextScale = 2;
constexpr int kBarHeight = 14;

std::string formatTicks(double ticks) {
  char text[32];
  if (ticks >= 1e6) std::snprintf(text, sizeof text, "%.3gM", ticks / 1e6);
  else if (ticks >= 1e3) std::snprintf(text, sizeof text, "%.3gk", ticks / 1e3);
  else std::snprintf(text, sizeof text, "%.3g", ticks);
  return text;
}

}  // namespace

CostScale costScale(const CostMap& map) {
  CostScale scale;
  if (map.ticks.empty()) return scale;
  std::vector<float> sorted = map.ticks;
  const auto quantile = [&](double q) {
    const std::size_t rank = std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())));
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(rank), sorted.end());
    return double(sorted[rank]);
  };
  scale.median = std::max(quantile(0.5), 1e-30);
  scale.top = std::max(quantile(0.99), scale.median);
  return scale;
}

Rgb8Image costMapImage(const CostMap& map, const std::string& title) {
  const CostScale scale = costScale(map);
  const int line = textLineHeight(kTextScale);
  const std::uint32_t width = std::max<std::uint32_t>(map.width, 320);
  // The caption at the labels' size when it fits, else at half that: never cut off at the image's edge.
  const std::string caption = title + ": median " + formatTicks(scale.median) + " ticks/sample";
  const int captionScale = textWidth(caption, kTextScale) <= int(width) - 16 ? kTextScale : 1;
  const int legendHeight = 4 + kBarHeight + 4 + line + 4 + line + 4;
  Rgb8Image image;
  image.width = width;
  image.height = map.height + std::uint32_t(legendHeight);
  image.rgb.assign(std::size_t(image.width) * image.height * 3, 24);
  for (std::uint32_t y = 0; y < map.height; ++y) {
    for (std::uint32_t x = 0; x < map.width; ++x) {
      const auto rgb = falseColour(map.ticks[std::size_t(y) * map.width + x] / scale.top);
      std::copy(rgb.begin(), rgb.end(), image.rgb.begin() + std::ptrdiff_t((std::size_t(y) * image.width + x) * 3));
    }
  }
  // The colour bar spans the scale from 0 to its top, with ticks at 0, the mean and the top.
  const int barLeft = 8, barRight = int(image.width) - 8;
  const int barTop = int(map.height) + 4;
  for (int y = barTop; y < barTop + kBarHeight; ++y) {
    for (int x = barLeft; x < barRight; ++x) {
      const auto rgb = falseColour(double(x - barLeft) / double(barRight - barLeft - 1));
      std::copy(rgb.begin(), rgb.end(), image.rgb.begin() + std::ptrdiff_t((std::size_t(y) * image.width + x) * 3));
    }
  }
  const int labelTop = barTop + kBarHeight + 4;
  const std::array<std::uint8_t, 3> white{230, 230, 230};
  // Each label centred under its value, kept inside the image; one that would overlap a label already drawn (the
  // median close to 0 or to the top) moves just clear of it, and is left out only when there is no room.
  std::vector<std::pair<int, int>> taken;
  const auto label = [&](double ticks, const std::string& text) {
    const int centre = barLeft + int(std::lround(std::clamp(ticks / scale.top, 0.0, 1.0) * (barRight - barLeft - 1)));
    const int width = textWidth(text, kTextScale);
    const auto inside = [&](int x) { return std::clamp(x, 0, std::max(0, int(image.width) - width)); };
    const auto clear = [&](int x) {
      for (const auto& [left, right] : taken) {
        if (x < right + 6 && x + width + 6 > left) return false;
      }
      return true;
    };
    int x = inside(centre - width / 2);
    for (const auto& [left, right] : taken) {
      if (clear(x)) break;
      const int after = inside(right + 6), before = inside(left - 6 - width);
      x = clear(after) ? after : before;
    }
    if (!clear(x)) return;
    taken.emplace_back(x, x + width);
    drawText(image, x, labelTop, text, kTextScale, white, 0, int(image.width));
  };
  char top[48];
  std::snprintf(top, sizeof top, "%.1fx", scale.top / scale.median);
  label(0.0, "0");
  label(scale.top, top);
  label(scale.median, "median");
  drawText(image, 8, labelTop + line + 4, caption, captionScale, white, 0, int(image.width));
  return image;
}

void writeCostMap(const std::string& pngPath, const CostMap& map, const std::string& title) {
  Image raw(map.width, map.height);
  for (std::size_t i = 0; i < map.ticks.size(); ++i) {
    for (int c = 0; c < 3; ++c) raw.rgba[i * 4 + c] = map.ticks[i];
    raw.rgba[i * 4 + 3] = 1.0f;
  }
  writePng(pngPath, costMapImage(map, title));
  writeExr(std::filesystem::path(pngPath).replace_extension(".exr").string(), raw);
}

}  // namespace raylab
