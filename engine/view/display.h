// The display pass: display.comp turns the accumulation buffer into an 8-bit image of the full render size
// (stretching the reduced-resolution image while the camera moves), which is then blitted to the swapchain
// image. The display image persists between frames: texels whose pixels have no sample yet keep the last
// picture, so a refinement pass in progress never flashes black.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "image/image.h"
#include "vk/device.h"
#include "vk/pipeline.h"

namespace raylab {

struct Display {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  DescriptorSet descriptors;
  VkImage image = VK_NULL_HANDLE;  // RGBA8; TRANSFER_SRC_OPTIMAL between frames, GENERAL while written
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  glm::uvec2 extent{0};
  bool linearBlit = false;  // the format supports linear filtering: a scaled blit is smooth
};

struct DisplaySettings {
  float exposure = 0.0f;  // stops
  ToneMap toneMap = ToneMap::kClamp;
  bool encodeSrgb = true;  // false when the swapchain format is sRGB (the blit encodes)
};

// Throws Error when the device cannot store to or blit from an RGBA8 image.
Display createDisplay(const Device& device, glm::uvec2 extent);
void destroyDisplay(const Device& device, Display& display);

// A new image size (the device must be idle); the image starts black.
void resizeDisplay(const Device& device, Display& display, glm::uvec2 extent);
// The accumulation buffer to read (after the renderer reallocated it; the device must be idle).
void bindAccumulation(const Device& device, const Display& display, VkBuffer accumulation);

// Clears the image to black (at creation, after a resize).
void recordClearDisplay(VkCommandBuffer cmd, const Display& display);
// Records the display pass: `source` pixels of accumulation over the whole image. `keepEmpty`: texels whose
// pixels have no sample yet are left as they are.
void recordDisplayPass(VkCommandBuffer cmd, const Display& display, glm::uvec2 source, const DisplaySettings& settings,
                       bool keepEmpty);
// Blits the whole display image over the whole swapchain image (scaled when the sizes differ) and leaves the
// swapchain image in TRANSFER_DST_OPTIMAL. The swapchain image's previous content is discarded.
void recordBlitToSwapchain(VkCommandBuffer cmd, const Display& display, VkImage target, VkExtent2D targetExtent);

}  // namespace raylab
