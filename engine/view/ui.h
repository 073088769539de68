// Dear ImGui on the viewer's window: Debian's libimgui (1.86) with its GLFW and Vulkan backends. The UI is
// drawn by a render pass over the swapchain image after the rendered image was blitted there.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "view/swapchain.h"
#include "view/window.h"
#include "vk/device.h"

namespace raylab {

struct Ui {
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  std::vector<VkFramebuffer> framebuffers;  // one per swapchain image
  VkFormat format = VK_FORMAT_UNDEFINED;
};

// Creates the ImGui context and both backends; uploads the font atlas. `window` must already have its own
// callbacks, which ImGui chains.
Ui createUi(const Instance& instance, const Device& device, const Window& window, const Swapchain& swapchain);
void destroyUi(const Device& device, Ui& ui);
// After the swapchain was recreated.
void recreateUiFramebuffers(const Device& device, Ui& ui, const Swapchain& swapchain);

// Starts an ImGui frame; build the panel between this and recordUi.
void beginUiFrame();
// Finishes the ImGui frame and records its render pass over swapchain image `imageIndex`, which must be in
// TRANSFER_DST_OPTIMAL (after the blit); leaves it in PRESENT_SRC_KHR. A frame that drew nothing (the panel
// hidden, no overlay) still makes the layout transition.
void recordUi(VkCommandBuffer cmd, const Ui& ui, const Swapchain& swapchain, std::uint32_t imageIndex);

// Whether ImGui wants the mouse or keyboard this frame (a slider drag, a text field): the camera leaves them.
bool uiWantsMouse();
bool uiWantsKeyboard();

}  // namespace raylab
