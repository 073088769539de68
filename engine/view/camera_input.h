// The camera's share of the window's input: cursor motion, held buttons and keys from GLFW, and the wheel and
// hot keys the window's callbacks collected, as the platform-free CameraInput of view_logic/camera_controller.h.
#pragma once

#include <glm/glm.hpp>

#include "view/window.h"
#include "view_logic/camera_controller.h"

namespace raylab {

// The cursor's last position, to turn positions into motion.
struct CursorTracker {
  glm::dvec2 last{0.0};
  bool seen = false;
};

CameraInput pollCameraInput(const Window& window, const WindowInput& input, CursorTracker& cursor);

}  // namespace raylab
