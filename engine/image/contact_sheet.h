// Contact sheets: equal square cells in rows under a title line, each cell with a label under it, on black.
// The linear sheet (for OpenEXR) carries the cells only; the display sheet (for PNG) adds the text after tone
// mapping, so that labels stay white at any exposure or tone curve and the EXR keeps pure radiance.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include <glm/glm.hpp>

#include "image/bitmap_text.h"
#include "image/image.h"

namespace raylab {

// At most this many cells side by side; longer sweeps wrap into balanced rows.
constexpr std::uint32_t kContactSheetMaxColumns = 8;

struct ContactSheetLayout {
  std::uint32_t count = 0;
  std::uint32_t cellSize = 0;
  std::uint32_t columns = 0;
  std::uint32_t rows = 0;
  std::uint32_t gap = 0;          // between cells and around the sheet
  int titleScale = 1;             // of the font (bitmap_text.h)
  int labelScale = 1;
  std::uint32_t titleHeight = 0;  // the band above the first row
  std::uint32_t labelHeight = 0;  // the band under each row of cells
  std::uint32_t width = 0;
  std::uint32_t height = 0;

  glm::uvec2 cellOrigin(std::uint32_t index) const;  // top-left pixel of cell `index`
};

// The labels' font scale is the largest, up to max(2, cellSize / 96), at which every label fits its cell; the
// title's is the largest up to that at which it fits the sheet. Text too wide even at scale 1 is clipped.
ContactSheetLayout layoutContactSheet(std::uint32_t count, std::uint32_t cellSize, const std::string& title,
                                      std::span<const std::string> labels);

// The cells (each cellSize square, in order) on a black sheet: linear radiance, no text.
Image composeContactSheet(const ContactSheetLayout& layout, std::span<const Image> cells);

// The tone-mapped sheet with the title and the labels drawn in.
Rgb8Image annotateContactSheet(const ContactSheetLayout& layout, const Image& sheet, float exposure, ToneMap toneMap,
                               const std::string& title, std::span<const std::string> labels);

}  // namespace raylab
