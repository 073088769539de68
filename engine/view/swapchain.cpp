#include "view/swapchain.h"

#include <algorithm>
#include <string>

#include "util/error.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

// The 8-bit formats the display pass can pack texels for (it writes sRGB-encoded bytes, which both the UNORM
// and the SRGB variants show as intended). UNORM first: copies and blits then move bytes untouched.
constexpr VkFormat kPreferredFormats[] = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                                          VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB};

VkSurfaceFormatKHR chooseFormat(const Device& device, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical, surface, &count, formats.data()));
  for (VkFormat wanted : kPreferredFormats) {
    for (const VkSurfaceFormatKHR& format : formats) {
      if (format.format != wanted || format.colorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) continue;
      VkFormatProperties properties;
      vkGetPhysicalDeviceFormatProperties(device.physical, format.format, &properties);
      constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
      if ((properties.optimalTilingFeatures & kNeeded) == kNeeded) return format;
    }
  }
  std::string offered;
  for (const VkSurfaceFormatKHR& format : formats) {
    offered += (offered.empty() ? "" : ", ") + std::to_string(format.format);
  }
  throw Error("the window surface offers no 8-bit RGBA/BGRA format that can be blitted (VkFormat ids: " +
              offered + ")");
}

VkImageView createView(const Device& device, VkImage image, VkFormat format) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  info.format = format;
  info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(device.handle, &info, nullptr, &view));
  setDebugName(device, view, "swapchain view");
  return view;
}

}  // namespace

Swapchain createSwapchain(const Device& device, VkSurfaceKHR surface, VkExtent2D framebuffer, VkSwapchainKHR old) {
  VkSurfaceCapabilitiesKHR capabilities;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physical, surface, &capabilities));
  constexpr VkImageUsageFlags kRequired = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if ((capabilities.supportedUsageFlags & kRequired) != kRequired) {
    throw Error("the window surface does not support transfer-destination and colour-attachment images");
  }

  Swapchain swapchain;
  const VkSurfaceFormatKHR format = chooseFormat(device, surface);
  swapchain.format = format.format;
  swapchain.usage = kRequired | (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  if (capabilities.currentExtent.width != UINT32_MAX) {
    swapchain.extent = capabilities.currentExtent;
  } else {
    swapchain.extent.width =
        std::clamp(framebuffer.width, capabilities.minImageExtent.width, capabilities.maxImageExtent.width);
    swapchain.extent.height =
        std::clamp(framebuffer.height, capabilities.minImageExtent.height, capabilities.maxImageExtent.height);
  }
  // One image more than the minimum, so that acquiring never waits for the presentation engine to let go.
  swapchain.minImageCount = capabilities.minImageCount + 1;
  if (capabilities.maxImageCount > 0) {
    swapchain.minImageCount = std::min(swapchain.minImageCount, capabilities.maxImageCount);
  }
  const VkCompositeAlphaFlagBitsKHR alpha =
      (capabilities.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
          ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
          : static_cast<VkCompositeAlphaFlagBitsKHR>(capabilities.supportedCompositeAlpha &
                                                    -capabilities.supportedCompositeAlpha);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = swapchain.minImageCount;
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = swapchain.extent;
  info.imageArrayLayers = 1;
  info.imageUsage = swapchain.usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = capabilities.currentTransform;
  info.compositeAlpha = alpha;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // the one mode every surface supports
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  VK_CHECK(vkCreateSwapchainKHR(device.handle, &info, nullptr, &swapchain.handle));
  setDebugName(device, VK_OBJECT_TYPE_SWAPCHAIN_KHR, reinterpret_cast<std::uint64_t>(swapchain.handle), "swapchain");

  std::uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(device.handle, swapchain.handle, &count, nullptr));
  swapchain.images.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(device.handle, swapchain.handle, &count, swapchain.images.data()));
  for (VkImage image : swapchain.images) {
    setDebugName(device, image, "swapchain image");
    swapchain.views.push_back(createView(device, image, swapchain.format));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(device.handle, &semaphoreInfo, nullptr, &semaphore));
    setDebugName(device, VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<std::uint64_t>(semaphore), "rendering finished");
    swapchain.renderFinished.push_back(semaphore);
  }
  return swapchain;
}

void destroySwapchain(const Device& device, Swapchain& swapchain) {
  for (VkSemaphore semaphore : swapchain.renderFinished) vkDestroySemaphore(device.handle, semaphore, nullptr);
  for (VkImageView view : swapchain.views) vkDestroyImageView(device.handle, view, nullptr);
  if (swapchain.handle != VK_NULL_HANDLE) vkDestroySwapchainKHR(device.handle, swapchain.handle, nullptr);
  swapchain = {};
}

}  // namespace raylab
