#include "view/display.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "image/heatmap.h"
#include "shared/display.h"
#include "util/error.h"
#include "vk/commands.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

constexpr std::uint32_t kWorkgroupSize = gpu::kDisplayWorkgroupSize;
constexpr VkImageLayout kRestingLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;

constexpr DescriptorBinding kBindings[] = {
    {gpu::kBindingDisplayAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {gpu::kBindingDisplayTexels, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {gpu::kBindingDisplayCompare, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
};

// To a transfer, from `srcStage`: every transition of the display's images ends in a copy or a blit.
void toTransfer(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                VkAccessFlags dstAccess, VkImageLayout oldLayout, VkImageLayout newLayout) {
  imageBarrier(cmd, image, {srcStage, srcAccess, oldLayout, VK_PIPELINE_STAGE_TRANSFER_BIT, dstAccess, newLayout});
}

// Resting layout to TRANSFER_DST, after the previous frame's reads (write-after-read), keeping the texels.
void beginWrite(VkCommandBuffer cmd, VkImage image) {
  toTransfer(cmd, image, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_ACCESS_TRANSFER_WRITE_BIT, kRestingLayout,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
}

void endWrite(VkCommandBuffer cmd, VkImage image) {
  toTransfer(cmd, image, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kRestingLayout);
}

DisplayImage createDisplayImage(const Device& device, VkFormat format, glm::uvec2 extent, const char* name) {
  DisplayImage result;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.x, extent.y, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(device.handle, &info, nullptr, &result.image));
  setDebugName(device, result.image, name);

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device.handle, result.image, &requirements);
  VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocateInfo.allocationSize = requirements.size;
  allocateInfo.memoryTypeIndex =
      findMemoryType(device, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  VK_CHECK(vkAllocateMemory(device.handle, &allocateInfo, nullptr, &result.memory));
  setDebugName(device, result.memory, name);
  VK_CHECK(vkBindImageMemory(device.handle, result.image, result.memory, 0));
  return result;
}

void destroyDisplayImage(const Device& device, DisplayImage& image) {
  if (image.image != VK_NULL_HANDLE) vkDestroyImage(device.handle, image.image, nullptr);
  if (image.memory != VK_NULL_HANDLE) vkFreeMemory(device.handle, image.memory, nullptr);
  image = {};
}

void createSized(const Device& device, Display& display, glm::uvec2 extent) {
  display.extent = extent;
  display.texels = createBuffer(device, VkDeviceSize(extent.x) * extent.y * 4,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                MemoryUse::kDevice, "display texels");
  writeStorageBuffer(device, display.kernel.descriptors.set, gpu::kBindingDisplayTexels, display.texels.handle);
  display.preview = createDisplayImage(device, display.format, extent, "display preview");
  display.refined = createDisplayImage(device, display.format, extent, "display refined");
}

void destroySized(const Device& device, Display& display) {
  destroyDisplayImage(device, display.refined);
  destroyDisplayImage(device, display.preview);
  destroyBuffer(device, display.texels);
}

std::uint32_t toneMapId(ToneMap toneMap) {
  switch (toneMap) {
    case ToneMap::kClamp: return gpu::kDisplayToneClamp;
    case ToneMap::kReinhard: return gpu::kDisplayToneReinhard;
    case ToneMap::kAces: return gpu::kDisplayToneAces;
  }
  return gpu::kDisplayToneClamp;
}

void blit(VkCommandBuffer cmd, const Display& display, VkImage source, glm::uvec2 sourceSize, VkImage target,
          glm::uvec2 targetSize, glm::ivec2 targetOffset = glm::ivec2(0)) {
  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {static_cast<std::int32_t>(sourceSize.x), static_cast<std::int32_t>(sourceSize.y), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[0] = {targetOffset.x, targetOffset.y, 0};
  region.dstOffsets[1] = {targetOffset.x + static_cast<std::int32_t>(targetSize.x),
                          targetOffset.y + static_cast<std::int32_t>(targetSize.y), 1};
  vkCmdBlitImage(cmd, source, kRestingLayout, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
                 display.linearBlit ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
}

}  // namespace

Display createDisplay(const Device& device, VkFormat format, glm::uvec2 extent) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
  constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                           VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if ((properties.optimalTilingFeatures & kNeeded) != kNeeded) {
    throw Error("the Vulkan device cannot copy and blit images of the window's format (VkFormat " +
                std::to_string(format) + ")");
  }
  Display display;
  display.format = format;
  display.linearBlit = (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
  display.kernel = createComputeKernel(device, "display.comp", kBindings, sizeof(gpu::DisplayParams));
  createSized(device, display, extent);
  return display;
}

void destroyDisplay(const Device& device, Display& display) {
  destroySized(device, display);
  destroyComputeKernel(device, display.kernel);
  display = {};
}

void resizeDisplay(const Device& device, Display& display, glm::uvec2 extent) {
  destroySized(device, display);
  createSized(device, display, extent);
}

void bindAccumulation(const Device& device, const Display& display, VkBuffer accumulation) {
  writeStorageBuffer(device, display.kernel.descriptors.set, gpu::kBindingDisplayAccumulation, accumulation);
}

void bindCompared(const Device& device, const Display& display, VkBuffer accumulation) {
  writeStorageBuffer(device, display.kernel.descriptors.set, gpu::kBindingDisplayCompare, accumulation);
}

void recordClearDisplay(VkCommandBuffer cmd, const Display& display) {
  const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  for (VkImage image : {display.preview.image, display.refined.image}) {
    // UNDEFINED: whatever the image held is discarded, which is the point.
    toTransfer(cmd, image, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
    endWrite(cmd, image);
  }
}

void recordDisplayRegions(VkCommandBuffer cmd, const Display& display, const DisplayImage& target, glm::uvec2 size,
                          const DisplaySettings& settings, std::span<const Tile> regions) {
  if (regions.empty()) return;
  gpu::DisplayParams params{};
  params.size = size;
  params.exposureScale = std::exp2(settings.exposure);
  params.toneMap = toneMapId(settings.toneMap);
  params.flags = display.format == VK_FORMAT_B8G8R8A8_UNORM || display.format == VK_FORMAT_B8G8R8A8_SRGB
                     ? gpu::kDisplayBgra
                     : 0u;
  constexpr std::uint32_t kModes[] = {gpu::kDisplayImage, gpu::kDisplaySplit, gpu::kDisplayDifference,
                                      gpu::kDisplayRelativeDifference};
  params.mode = kModes[static_cast<int>(settings.mode)];
  params.splitColumn = static_cast<std::uint32_t>(std::lround(settings.divider * float(size.x)));
  params.differenceScale = settings.differenceScale > 0.0f ? settings.differenceScale : 1.0f;
  // The previous frame's copies read the texel buffer: write after them.
  VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0,
                       nullptr, 0, nullptr);
  std::vector<VkBufferImageCopy> copies;
  for (const Tile& region : regions) {
    params.regionOrigin = region.origin;
    recordDispatch(cmd, display.kernel, &params, (region.size.x + kWorkgroupSize - 1) / kWorkgroupSize,
                   (region.size.y + kWorkgroupSize - 1) / kWorkgroupSize);
    VkBufferImageCopy copy{};
    copy.bufferOffset = (VkDeviceSize(region.origin.y) * size.x + region.origin.x) * 4;
    copy.bufferRowLength = size.x;
    copy.bufferImageHeight = size.y;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageOffset = {static_cast<std::int32_t>(region.origin.x), static_cast<std::int32_t>(region.origin.y), 0};
    copy.imageExtent = {region.size.x, region.size.y, 1};
    copies.push_back(copy);
  }
  VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &after, 0,
                       nullptr, 0, nullptr);
  beginWrite(cmd, target.image);
  vkCmdCopyBufferToImage(cmd, display.texels.handle, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(copies.size()), copies.data());
  endWrite(cmd, target.image);
}

void recordPreviewToRefined(VkCommandBuffer cmd, const Display& display, glm::uvec2 previewSize) {
  beginWrite(cmd, display.refined.image);
  blit(cmd, display, display.preview.image, previewSize, display.refined.image, display.extent);
  endWrite(cmd, display.refined.image);
}

void recordToSwapchain(VkCommandBuffer cmd, const Display& display, const DisplayImage& source, glm::uvec2 size,
                       VkImage target, VkRect2D area) {
  // The acquire semaphore orders this after the presentation engine's read; UNDEFINED drops the old content.
  toTransfer(cmd, target, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  if (area.offset.x > 0 || area.offset.y > 0) {
    // The panel's strip: a dark grey the panel is drawn on, so that nothing undefined shows through.
    const VkClearColorValue grey{{0.08f, 0.08f, 0.09f, 1.0f}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &grey, 1, &range);
    toTransfer(cmd, target, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  }
  const glm::uvec2 targetSize(area.extent.width, area.extent.height);
  if (size == targetSize) {
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffset = {area.offset.x, area.offset.y, 0};
    region.extent = {size.x, size.y, 1};
    vkCmdCopyImage(cmd, source.image, kRestingLayout, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else {
    blit(cmd, display, source.image, size, target, targetSize, glm::ivec2(area.offset.x, area.offset.y));
  }
}

Rgb8Image displayedImage(const Image& a, const Image* b, const DisplaySettings& settings) {
  Rgb8Image shown;
  shown.width = a.width;
  shown.height = a.height;
  shown.rgb.resize(std::size_t(a.width) * a.height * 3);
  const DisplayMode mode = b == nullptr ? DisplayMode::kImage : settings.mode;
  const std::uint32_t splitColumn = static_cast<std::uint32_t>(std::lround(settings.divider * float(a.width)));
  const float scale = settings.differenceScale > 0.0f ? settings.differenceScale : 1.0f;
  for (std::uint32_t y = 0; y < a.height; ++y) {
    for (std::uint32_t x = 0; x < a.width; ++x) {
      std::uint8_t* out = &shown.rgb[(std::size_t(y) * a.width + x) * 3];
      if (mode == DisplayMode::kDifference || mode == DisplayMode::kRelativeDifference) {
        const glm::vec3 left(a.at(x, y)), right(b->at(x, y));
        const glm::vec3 difference = glm::abs(left - right);
        float value = std::max({difference.r, difference.g, difference.b});
        if (mode == DisplayMode::kRelativeDifference) {
          const float level = std::max({left.r, left.g, left.b, right.r, right.g, right.b});
          value = level > 0.0f ? value / level : 0.0f;
        }
        const auto rgb = falseColour(double(value / scale));
        std::copy(rgb.begin(), rgb.end(), out);
      } else {
        const bool compared = mode == DisplayMode::kSplit && x >= splitColumn;
        const glm::vec4 radiance = compared ? b->at(x, y) : a.at(x, y);
        for (int c = 0; c < 3; ++c) out[c] = toDisplay(radiance[c], settings.exposure, settings.toneMap);
      }
    }
  }
  return shown;
}

}  // namespace raylab
