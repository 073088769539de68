#include "image/contact_sheet.h"

#include <algorithm>

#include "util/error.h"

namespace raylab {

namespace {

// Text grows with the cells: at most one font scale per 96 pixels of cell, and at least 2 (12-pixel glyphs
// at scale 1 are hard to read once a browser shrinks a wide sheet).
constexpr std::uint32_t kCellPixelsPerScale = 96;
constexpr std::array<std::uint8_t, 3> kTextColour{230, 230, 230};

// The largest scale in [1, maxScale] at which `text` is at most `width` pixels wide; 1 if none.
int fittingScale(const std::string& text, int width, int maxScale) {
  int scale = 1;
  while (scale < maxScale && textWidth(text, scale + 1) <= width) ++scale;
  return scale;
}

}  // namespace

glm::uvec2 ContactSheetLayout::cellOrigin(std::uint32_t index) const {
  const std::uint32_t row = index / columns, column = index % columns;
  return {gap + column * (cellSize + gap), titleHeight + row * (cellSize + labelHeight)};
}

ContactSheetLayout layoutContactSheet(std::uint32_t count, std::uint32_t cellSize, const std::string& title,
                                      std::span<const std::string> labels) {
  if (count == 0 || cellSize == 0) throw Error("contact sheet: no cells");
  ContactSheetLayout layout;
  layout.count = count;
  layout.cellSize = cellSize;
  layout.rows = (count + kContactSheetMaxColumns - 1) / kContactSheetMaxColumns;
  layout.columns = (count + layout.rows - 1) / layout.rows;  // 10 cells: two rows of 5, not 8 and 2
  layout.gap = std::max(2u, cellSize / 32);
  layout.width = layout.columns * cellSize + (layout.columns + 1) * layout.gap;

  const int maxScale = int(std::max(2u, cellSize / kCellPixelsPerScale));
  layout.labelScale = maxScale;
  for (const std::string& label : labels) {
    layout.labelScale = std::min(layout.labelScale, fittingScale(label, int(cellSize), maxScale));
  }
  // One size of text throughout, unless the title needs a smaller one to fit.
  layout.titleScale = fittingScale(title, int(layout.width - 2 * layout.gap), layout.labelScale);
  // stb_easy_font's glyphs fill about 10 of their 12-unit line; the rest is the band's padding.
  layout.titleHeight = layout.gap + std::uint32_t(textLineHeight(layout.titleScale)) + layout.gap;
  layout.labelHeight = layout.gap + std::uint32_t(textLineHeight(layout.labelScale));
  layout.height = layout.titleHeight + layout.rows * (cellSize + layout.labelHeight);
  return layout;
}

Image composeContactSheet(const ContactSheetLayout& layout, std::span<const Image> cells) {
  if (cells.size() != layout.count) throw Error("contact sheet: cell count differs from the layout's");
  Image sheet(layout.width, layout.height);
  for (std::uint32_t i = 0; i < layout.count; ++i) {
    const Image& cell = cells[i];
    if (cell.width != layout.cellSize || cell.height != layout.cellSize) {
      throw Error("contact sheet: cell " + std::to_string(i) + " is not " + std::to_string(layout.cellSize) +
                  " pixels square");
    }
    const glm::uvec2 origin = layout.cellOrigin(i);
    for (std::uint32_t y = 0; y < cell.height; ++y) {
      std::copy_n(&cell.rgba[std::size_t(y) * cell.width * 4], std::size_t(cell.width) * 4,
                  &sheet.rgba[(std::size_t(origin.y + y) * sheet.width + origin.x) * 4]);
    }
  }
  // Alpha 1 everywhere: the bands are black, not transparent.
  for (std::size_t i = 3; i < sheet.rgba.size(); i += 4) sheet.rgba[i] = 1.0f;
  return sheet;
}

Rgb8Image annotateContactSheet(const ContactSheetLayout& layout, const Image& sheet, float exposure, ToneMap toneMap,
                               const std::string& title, std::span<const std::string> labels) {
  Rgb8Image display;
  display.width = sheet.width;
  display.height = sheet.height;
  display.rgb.resize(std::size_t(sheet.width) * sheet.height * 3);
  for (std::size_t i = 0; i < std::size_t(sheet.width) * sheet.height; ++i) {
    for (int c = 0; c < 3; ++c) display.rgb[i * 3 + c] = toDisplay(sheet.rgba[i * 4 + c], exposure, toneMap);
  }
  const int right = int(layout.width - layout.gap);
  drawText(display, int(layout.gap), int(layout.gap), title, layout.titleScale, kTextColour, int(layout.gap), right);
  for (std::uint32_t i = 0; i < labels.size() && i < layout.count; ++i) {
    const glm::uvec2 origin = layout.cellOrigin(i);
    const int width = textWidth(labels[i], layout.labelScale);
    // Centred under the cell; a label wider than the cell starts at its left edge and is clipped.
    const int x = int(origin.x) + std::max(0, (int(layout.cellSize) - width) / 2);
    const int y = int(origin.y + layout.cellSize + layout.gap / 2);
    drawText(display, x, y, labels[i], layout.labelScale, kTextColour, int(origin.x),
             int(origin.x + layout.cellSize));
  }
  return display;
}

}  // namespace raylab
