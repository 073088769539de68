// The mouse over the image, besides the camera: dragging the split view's divider, clicking a pixel (picking)
// and hovering. Window-free: the viewer feeds it the cursor and the left button each frame.
#pragma once

#include <optional>

#include <glm/glm.hpp>

namespace raylab {

inline constexpr float kDividerGrabPixels = 6.0f;  // the divider is grabbed this close to its line
inline constexpr float kClickSlopPixels = 3.0f;    // a press and release this close together is a click

struct PointerInput {
  glm::vec2 cursor{0.0f};       // window pixels
  bool left = false;            // left button held
  bool uiWantsMouse = false;    // over the panel or an ImGui widget
  glm::vec2 imageOrigin{0.0f};  // the image's rectangle in the window
  glm::vec2 imageSize{1.0f};
  std::optional<float> divider;  // the split view's divider as a fraction of the width, when it shows
};

struct PointerState {
  enum class Mode { kIdle, kPressed, kDraggingDivider, kElsewhere };
  Mode mode = Mode::kIdle;
  glm::vec2 pressedAt{0.0f};
  float travel = 0.0f;  // the longest distance from pressedAt while held
};

struct PointerEvents {
  bool cameraBlocked = false;      // the divider is being dragged: the camera must not orbit
  std::optional<float> divider;    // its new position
  std::optional<glm::vec2> click;  // where a click landed, as a fraction of the image (x right, y down)
  std::optional<glm::vec2> hover;  // where the cursor rests over the image, likewise
};

PointerEvents updatePointer(PointerState& state, const PointerInput& input);

// The pixel of a width x height image under `fraction` (clamped to the image).
glm::uvec2 pixelAt(glm::vec2 fraction, glm::uvec2 size);

}  // namespace raylab
