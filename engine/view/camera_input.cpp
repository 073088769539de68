#include "view/camera_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab {

namespace {

bool held(GLFWwindow* window, int key) { return glfwGetKey(window, key) == GLFW_PRESS; }

}  // namespace

CameraInput pollCameraInput(const Window& window, const WindowInput& input, CursorTracker& cursor) {
  GLFWwindow* handle = window.handle;
  CameraInput camera;
  glm::dvec2 position;
  glfwGetCursorPos(handle, &position.x, &position.y);
  camera.cursorDelta = cursor.seen ? glm::vec2(position - cursor.last) : glm::vec2(0.0f);
  cursor.last = position;
  cursor.seen = true;

  int width = 1, height = 1;
  glfwGetWindowSize(handle, &width, &height);
  camera.viewHeight = float(height);
  camera.shift = held(handle, GLFW_KEY_LEFT_SHIFT) || held(handle, GLFW_KEY_RIGHT_SHIFT);
  camera.left = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  camera.middle = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  camera.right = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  camera.fly = glm::vec3(float(held(handle, GLFW_KEY_D)) - float(held(handle, GLFW_KEY_A)),
                         float(held(handle, GLFW_KEY_E)) - float(held(handle, GLFW_KEY_Q)),
                         float(held(handle, GLFW_KEY_W)) - float(held(handle, GLFW_KEY_S)));
  camera.scroll = input.scroll;
  for (int key : input.keysPressed) camera.reset |= key == GLFW_KEY_R || key == GLFW_KEY_HOME;
  return camera;
}

}  // namespace raylab
