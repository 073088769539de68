// The display pass and the images it feeds. display.comp turns the accumulation buffer into 8-bit texels in
// a buffer, already in the byte order and encoding of the swapchain's format; transfer commands then move
// them: copies where sizes match, blits where the picture is stretched. (On lavapipe a blit is a draw, about
// as costly as the display pass itself at 1280x720, while a copy is a memcpy.) Two images of the full render
// size, in the swapchain's format:
//   - `preview` holds the reduced-resolution image traced while the view changes, in its top-left corner;
//     the blit to the window stretches it.
//   - `refined` holds the full-resolution image while refining. It keeps its texels between frames, so only
//     the tiles traced in a frame go through the display pass and the copy; when refinement starts, the last
//     preview is stretched into it, and stands in for the pixels the first pass has not reached yet.
#pragma once

#include <vulkan/vulkan.h>

#include <span>

#include <glm/glm.hpp>

#include "image/image.h"
#include "view_logic/scheduler.h"
#include "vk/device.h"
#include "vk/compute_kernel.h"
#include "vk/resources.h"

namespace raylab {

// TRANSFER_SRC_OPTIMAL between frames; TRANSFER_DST_OPTIMAL while a copy or blit writes it.
struct DisplayImage {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
};

struct Display {
  ComputeKernel kernel;       // display.comp; its set binds the accumulation buffer and `texels`
  Buffer texels;              // one packed 8-bit texel per pixel of the full render size
  DisplayImage preview;
  DisplayImage refined;
  VkFormat format = VK_FORMAT_UNDEFINED;  // the swapchain's
  glm::uvec2 extent{0};                   // of both images: the full render size
  bool linearBlit = false;                // the format filters linearly: stretched blits are smooth
};

// What the display pass shows: the image, or with a comparison the split view or a difference.
enum class DisplayMode { kImage, kSplit, kDifference, kRelativeDifference };

struct DisplaySettings {
  float exposure = 0.0f;  // stops
  ToneMap toneMap = ToneMap::kClamp;
  DisplayMode mode = DisplayMode::kImage;
  float divider = 0.5f;            // kSplit: the fraction of the width where the compared image starts
  float differenceScale = 0.1f;    // a difference this large shows at the top of the colour ramp

  bool operator==(const DisplaySettings&) const = default;
};

// What the display pass shows for accumulated images `a` and (comparing) `b` under `settings`, computed on the
// host as display.comp computes it: the screenshot's PNG "as displayed" (split, difference or the image).
Rgb8Image displayedImage(const Image& a, const Image* b, const DisplaySettings& settings);

// Images in `format` (the swapchain's: B8G8R8A8 or R8G8B8A8, UNORM or SRGB). Throws Error when the device
// cannot copy and blit it.
Display createDisplay(const Device& device, VkFormat format, glm::uvec2 extent);
void destroyDisplay(const Device& device, Display& display);

// A new size (the device must be idle); both images start black.
void resizeDisplay(const Device& device, Display& display, glm::uvec2 extent);
// The accumulation buffer to read (after the renderer reallocated it; the device must be idle), and the
// compared image's (the split view; the same buffer when nothing is compared).
void bindAccumulation(const Device& device, const Display& display, VkBuffer accumulation);
void bindCompared(const Device& device, const Display& display, VkBuffer accumulation);

// Clears both images to black (after creation and resizes).
void recordClearDisplay(VkCommandBuffer cmd, const Display& display);
// The display pass for the `regions` of an accumulation of `size` pixels, and their copy into `target`
// (preview or refined) at the same places.
void recordDisplayRegions(VkCommandBuffer cmd, const Display& display, const DisplayImage& target, glm::uvec2 size,
                          const DisplaySettings& settings, std::span<const Tile> regions);
// Stretches the preview's top-left `previewSize` texels over the whole refined image.
void recordPreviewToRefined(VkCommandBuffer cmd, const Display& display, glm::uvec2 previewSize);
// Puts the top-left `size` texels of `source` over `area` of the swapchain image (a copy at equal sizes, else a
// stretching blit) and clears the rest (the panel's strip), leaving the swapchain image in TRANSFER_DST_OPTIMAL;
// its previous content is discarded.
void recordToSwapchain(VkCommandBuffer cmd, const Display& display, const DisplayImage& source, glm::uvec2 size,
                       VkImage target, VkRect2D area);

}  // namespace raylab
