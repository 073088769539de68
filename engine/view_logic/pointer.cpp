#include "view_logic/pointer.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

bool insideImage(const PointerInput& input) {
  const glm::vec2 local = input.cursor - input.imageOrigin;
  return local.x >= 0.0f && local.y >= 0.0f && local.x < input.imageSize.x && local.y < input.imageSize.y;
}

glm::vec2 imageFraction(const PointerInput& input) {
  return glm::clamp((input.cursor - input.imageOrigin) / input.imageSize, glm::vec2(0.0f), glm::vec2(1.0f));
}

}  // namespace

PointerEvents updatePointer(PointerState& state, const PointerInput& input) {
  PointerEvents events;
  using Mode = PointerState::Mode;
  if (!input.left) {
    if (state.mode == Mode::kPressed && state.travel <= kClickSlopPixels) events.click = imageFraction(input);
    state.mode = Mode::kIdle;
    if (!input.uiWantsMouse && insideImage(input)) events.hover = imageFraction(input);
    return events;
  }
  if (state.mode == Mode::kIdle) {
    // A new press: on the divider, on the image, or somewhere the pointer leaves alone (the panel).
    state.pressedAt = input.cursor;
    state.travel = 0.0f;
    if (input.uiWantsMouse || !insideImage(input)) {
      state.mode = Mode::kElsewhere;
    } else if (input.divider &&
               std::abs(input.cursor.x - (input.imageOrigin.x + *input.divider * input.imageSize.x)) <= kDividerGrabPixels) {
      state.mode = Mode::kDraggingDivider;
    } else {
      state.mode = Mode::kPressed;
    }
  }
  state.travel = std::max(state.travel, glm::length(input.cursor - state.pressedAt));
  if (state.mode == Mode::kDraggingDivider) {
    events.cameraBlocked = true;
    events.divider = std::clamp((input.cursor.x - input.imageOrigin.x) / input.imageSize.x, 0.0f, 1.0f);
  }
  return events;
}

glm::uvec2 pixelAt(glm::vec2 fraction, glm::uvec2 size) {
  const glm::vec2 scaled = glm::floor(glm::clamp(fraction, glm::vec2(0.0f), glm::vec2(1.0f)) * glm::vec2(size));
  return glm::min(glm::uvec2(scaled), size - glm::uvec2(1));
}

}  // namespace raylab
