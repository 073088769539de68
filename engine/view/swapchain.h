// The window's swapchain: format and usage chosen from what the surface reports, FIFO presentation, and
// one "rendering finished" semaphore per image (a present may still wait on it when the next frame starts).
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "vk/device.h"

namespace raylab {

struct Swapchain {
  VkSwapchainKHR handle = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
  VkImageUsageFlags usage = 0;  // TRANSFER_DST and COLOR_ATTACHMENT always; TRANSFER_SRC when offered
  std::uint32_t minImageCount = 0;
  std::vector<VkImage> images;
  std::vector<VkImageView> views;
  std::vector<VkSemaphore> renderFinished;
};

// `framebuffer` is the window's size in pixels; the surface's current extent wins where it is defined.
// `old` (may be null) is retired by the new swapchain; destroy it afterwards. Throws Error naming what the
// surface lacks (a B8G8R8A8/R8G8B8A8 format, transfer-destination or colour-attachment usage).
Swapchain createSwapchain(const Device& device, VkSurfaceKHR surface, VkExtent2D framebuffer,
                          VkSwapchainKHR old = VK_NULL_HANDLE);
void destroySwapchain(const Device& device, Swapchain& swapchain);

}  // namespace raylab
