// Camera motion for the viewer: orbit around the target, pan, zoom and fly, as pure functions on Camera
// (scripts call them directly) plus the mapping from one frame's mouse and keyboard state to them (the window
// reads that state: view/camera_input.h). Every operation keeps the camera valid for applyCamera: the view
// direction never becomes parallel to the up vector.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// Rotates the position around the target: `yaw` about the up axis, `pitch` about the camera's right axis
// (positive looks down from higher up), radians. Pitch stops short of the poles.
void orbitCamera(Camera& camera, float yaw, float pitch);
// Moves position and target together by (dx, dy) times the view height at the target's distance.
void panCamera(Camera& camera, float dx, float dy);
// Multiplies the distance to the target by `factor` (< 1 moves closer), never closer than `minDistance`.
void zoomCamera(Camera& camera, float factor, float minDistance);
// Turns the view around the position (yaw, pitch in radians), keeping the target at the same distance ahead.
void lookCamera(Camera& camera, float yaw, float pitch);
// Moves position and target by `move` in camera space: x right, y up, z forward.
void flyCamera(Camera& camera, glm::vec3 move);

// The size of the scene (diagonal of its bounds): fly speed and zoom limits scale with it.
float sceneSize(const Scene& scene);

struct CameraController {
  Camera home;  // what "reset view" returns to
  float sceneSize = 1.0f;
};

CameraController makeCameraController(const Scene& scene);

// One frame of the mouse and the keyboard, as far as the camera cares.
struct CameraInput {
  glm::vec2 cursorDelta{0.0f};  // pixels the cursor moved since the last frame
  float viewHeight = 1.0f;      // pixels: pan moves the scene with the cursor
  bool shift = false;
  bool left = false;            // buttons held
  bool middle = false;
  bool right = false;
  glm::vec3 fly{0.0f};          // keys held while flying: x right (D - A), y up (E - Q), z forward (W - S)
  double scroll = 0.0;          // wheel steps, positive away from the user
  bool reset = false;           // R or Home was pressed
};

// Applies this frame's input to `camera`; true when it moved. `mouseFree`/`keyboardFree`: the UI does not want
// them. `seconds`: time since the last call (fly speed).
bool updateCamera(const CameraController& controller, Camera& camera, const CameraInput& input, bool mouseFree,
                  bool keyboardFree, double seconds);

}  // namespace raylab
