// The comparison's ImGui parts: the panel's Compare and Pick sections, and the overlay over the image (the
// labels of the two sides, the divider, the difference view's colour bar, the hovered material's name). They edit
// plain values and report what changed; viewer_compare.cpp acts on it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "render/renderer.h"
#include "scene/scene.h"

namespace raylab {

enum class CompareShow { kSplit, kDifference, kRelativeDifference };

struct CompareView {
  CompareShow show = CompareShow::kSplit;
  float divider = 0.5f;          // where the right side starts, as a fraction of the image's width
  float differenceScale = 0.1f;  // the difference at the top of the colour bar
};

// Mean and largest |A - B| (the largest channel; relative: over the larger of A and B) over the image in view.
struct DifferenceStats {
  bool valid = false;
  double mean = 0.0;
  double max = 0.0;
  std::uint32_t spp = 0;  // when they were measured
};

struct PickedPixel {
  glm::uvec2 pixel{0};
  std::string material;  // its name, or "(background)"
  PixelValue left;
  std::optional<PixelValue> right;
};

struct CompareEdits {
  bool start = false;         // compare the selected material (the right side starts as a copy of it)
  bool stop = false;
  bool rightChanged = false;  // the right side's model or parameters
};

// The Compare section. `compared`: the material on the right side when comparing; `right` its record there.
CompareEdits drawCompareSection(const Scene& scene, std::size_t selectedMaterial, std::optional<std::uint32_t> compared,
                                gpu::MaterialRecord& right, CompareView& view, const DifferenceStats& stats);
void drawPickSection(const std::optional<PickedPixel>& picked);

struct OverlayText {
  std::string left;   // the sides' labels, empty without a comparison
  std::string right;
  std::string hover;  // the material under the cursor, empty for none
};

// Over the image's rectangle in the window: labels and the divider (split), or the colour bar with its scale
// (difference), and the hover text next to the cursor.
void drawCompareOverlay(glm::vec2 imageOrigin, glm::vec2 imageSize, const CompareView& view, const OverlayText& text,
                        glm::vec2 cursor);

}  // namespace raylab
