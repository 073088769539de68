#include "view/window.h"

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>

#include "util/error.h"
#include "util/timer.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

std::string gLastGlfwError;  // GLFW reports errors through a callback only; the main thread reads it

void onGlfwError(int, const char* description) { gLastGlfwError = description; }

WindowInput& inputOf(GLFWwindow* handle) { return *static_cast<WindowInput*>(glfwGetWindowUserPointer(handle)); }

void onScroll(GLFWwindow* handle, double, double dy) {
  inputOf(handle).scroll += dy;
  inputOf(handle).activity = true;
}

void onKey(GLFWwindow* handle, int key, int, int action, int) {
  if (action == GLFW_PRESS) inputOf(handle).keysPressed.push_back(key);
  inputOf(handle).activity = true;
}

void onActivity(GLFWwindow* handle) { inputOf(handle).activity = true; }

}  // namespace

bool initWindowSystem(std::string& error) {
  glfwSetErrorCallback(onGlfwError);
  if (glfwInit() != GLFW_TRUE) {
    error = gLastGlfwError.empty() ? "glfwInit failed" : gLastGlfwError;
    return false;
  }
  if (glfwVulkanSupported() != GLFW_TRUE) {
    error = "GLFW found no Vulkan loader";
    glfwTerminate();
    return false;
  }
  return true;
}

void terminateWindowSystem() { glfwTerminate(); }

std::vector<const char*> windowInstanceExtensions() {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) throw Error("the window system offers no Vulkan surface extension: " + gLastGlfwError);
  return std::vector<const char*>(names, names + count);
}

Window createWindow(VkInstance instance, std::uint32_t width, std::uint32_t height, const std::string& title) {
  Window window;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window.handle = glfwCreateWindow(static_cast<int>(width), static_cast<int>(height), title.c_str(), nullptr, nullptr);
  if (window.handle == nullptr) throw Error("cannot create a window: " + gLastGlfwError);
  window.input = std::make_unique<WindowInput>();
  glfwSetWindowUserPointer(window.handle, window.input.get());
  glfwSetScrollCallback(window.handle, onScroll);
  glfwSetKeyCallback(window.handle, onKey);
  glfwSetCursorPosCallback(window.handle, [](GLFWwindow* h, double, double) { onActivity(h); });
  glfwSetMouseButtonCallback(window.handle, [](GLFWwindow* h, int, int, int) { onActivity(h); });
  glfwSetCharCallback(window.handle, [](GLFWwindow* h, unsigned) { onActivity(h); });
  glfwSetFramebufferSizeCallback(window.handle, [](GLFWwindow* h, int, int) { onActivity(h); });
  glfwSetWindowRefreshCallback(window.handle, onActivity);

  const VkResult result = glfwCreateWindowSurface(instance, window.handle, nullptr, &window.surface);
  if (result != VK_SUCCESS) {
    glfwDestroyWindow(window.handle);
    throw Error(std::string("cannot create a Vulkan surface for the window: ") + vkResultName(result) + " " +
                gLastGlfwError);
  }
  return window;
}

void destroyWindow(VkInstance instance, Window& window) {
  if (window.surface != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance, window.surface, nullptr);
  if (window.handle != nullptr) glfwDestroyWindow(window.handle);
  window = {};
}

VkExtent2D framebufferExtent(const Window& window) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window.handle, &width, &height);
  return {static_cast<std::uint32_t>(std::max(width, 0)), static_cast<std::uint32_t>(std::max(height, 0))};
}

bool requestWindowSize(Window& window, std::uint32_t width, std::uint32_t height, double timeoutSeconds) {
  glfwSetWindowSize(window.handle, static_cast<int>(width), static_cast<int>(height));
  const Stopwatch clock;
  while (clock.seconds() < timeoutSeconds) {
    glfwWaitEventsTimeout(0.01);
    int w = 0, h = 0;
    glfwGetWindowSize(window.handle, &w, &h);
    if (w == static_cast<int>(width) && h == static_cast<int>(height)) return true;
  }
  return false;
}

WindowInput takeInput(Window& window) {
  WindowInput taken = std::move(*window.input);
  *window.input = {};
  return taken;
}

bool windowShouldClose(const Window& window) { return glfwWindowShouldClose(window.handle) == GLFW_TRUE; }

void requestWindowClose(Window& window) { glfwSetWindowShouldClose(window.handle, GLFW_TRUE); }

}  // namespace raylab
