// The viewer's window: GLFW on X11, its Vulkan surface, and the input that arrives through callbacks (wheel,
// key presses). Mouse position and held buttons are polled from GLFW directly by the camera controller.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace raylab {

// What callbacks collected since the viewer last took it.
struct WindowInput {
  double scroll = 0.0;           // wheel steps, positive away from the user
  std::vector<int> keysPressed;  // GLFW key codes, in order: edge-triggered hot keys
  bool activity = false;         // any event at all: the viewer draws a frame for it even when idle
};

struct Window {
  GLFWwindow* handle = nullptr;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  // Behind a pointer so that GLFW's user pointer stays valid when the Window struct moves.
  std::unique_ptr<WindowInput> input;
};

// glfwInit. False without a usable display; `error` then says why (GLFW's own words).
bool initWindowSystem(std::string& error);
void terminateWindowSystem();

// The instance extensions the window system needs for surfaces (VK_KHR_surface and VK_KHR_xcb_surface on X11).
std::vector<const char*> windowInstanceExtensions();

// A resizable window without a client API, its surface on `instance`, and the input callbacks. Must be created
// before ImGui's GLFW backend, which chains these callbacks.
Window createWindow(VkInstance instance, std::uint32_t width, std::uint32_t height, const std::string& title);
void destroyWindow(VkInstance instance, Window& window);

// The size of the drawable area in pixels; zero while minimised.
VkExtent2D framebufferExtent(const Window& window);

// Asks the window system for a new size and waits (up to `timeoutSeconds`) until the framebuffer has it.
// Returns false when it did not happen in time (a window manager may refuse).
bool requestWindowSize(Window& window, std::uint32_t width, std::uint32_t height, double timeoutSeconds);

WindowInput takeInput(Window& window);
bool windowShouldClose(const Window& window);
void requestWindowClose(Window& window);

}  // namespace raylab
