#include "view/display.h"

#include <cmath>

#include "shared/display.h"
#include "util/error.h"
#include "vk/debug_name.h"
#include "vk/resources.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_UNORM;  // display.comp declares rgba8
constexpr std::uint32_t kWorkgroupSize = 8;                    // display.comp: local_size 8 x 8
// Between frames the image waits for the blit; the display pass moves it to GENERAL and back.
constexpr VkImageLayout kRestingLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;

constexpr DescriptorBinding kBindings[] = {
    {gpu::kBindingDisplayAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {gpu::kBindingDisplayImage, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
};

void createImage(const Device& device, Display& display, glm::uvec2 extent) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kDisplayFormat;
  info.extent = {extent.x, extent.y, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(device.handle, &info, nullptr, &display.image));
  setDebugName(device, display.image, "display image");

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device.handle, display.image, &requirements);
  VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocateInfo.allocationSize = requirements.size;
  allocateInfo.memoryTypeIndex =
      findMemoryType(device, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  VK_CHECK(vkAllocateMemory(device.handle, &allocateInfo, nullptr, &display.memory));
  setDebugName(device, display.memory, "display image memory");
  VK_CHECK(vkBindImageMemory(device.handle, display.image, display.memory, 0));

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = display.image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = kDisplayFormat;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VK_CHECK(vkCreateImageView(device.handle, &viewInfo, nullptr, &display.view));
  setDebugName(device, display.view, "display image view");
  display.extent = extent;

  VkDescriptorImageInfo imageInfo{VK_NULL_HANDLE, display.view, VK_IMAGE_LAYOUT_GENERAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = display.descriptors.set;
  write.dstBinding = gpu::kBindingDisplayImage;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  write.pImageInfo = &imageInfo;
  vkUpdateDescriptorSets(device.handle, 1, &write, 0, nullptr);
}

void destroyImage(const Device& device, Display& display) {
  if (display.view != VK_NULL_HANDLE) vkDestroyImageView(device.handle, display.view, nullptr);
  if (display.image != VK_NULL_HANDLE) vkDestroyImage(device.handle, display.image, nullptr);
  if (display.memory != VK_NULL_HANDLE) vkFreeMemory(device.handle, display.memory, nullptr);
  display.view = VK_NULL_HANDLE;
  display.image = VK_NULL_HANDLE;
  display.memory = VK_NULL_HANDLE;
}

std::uint32_t toneMapId(ToneMap toneMap) {
  switch (toneMap) {
    case ToneMap::kClamp: return gpu::kDisplayToneClamp;
    case ToneMap::kReinhard: return gpu::kDisplayToneReinhard;
    case ToneMap::kAces: return gpu::kDisplayToneAces;
  }
  return gpu::kDisplayToneClamp;
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess, VkImageLayout oldLayout,
                  VkImageLayout newLayout) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = oldLayout;
  barrier.newLayout = newLayout;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace

Display createDisplay(const Device& device, glm::uvec2 extent) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(device.physical, kDisplayFormat, &properties);
  constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT;
  if ((properties.optimalTilingFeatures & kNeeded) != kNeeded) {
    throw Error("the Vulkan device cannot use R8G8B8A8_UNORM images as storage images and blit sources");
  }
  Display display;
  display.linearBlit = (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
  display.setLayout = createDescriptorSetLayout(device, kBindings, "display set layout");
  display.pipelineLayout =
      createPipelineLayout(device, display.setLayout, sizeof(gpu::DisplayParams), "display pipeline layout");
  display.pipeline = createComputePipeline(device, display.pipelineLayout, "display.comp");
  display.descriptors = allocateDescriptorSet(device, display.setLayout, kBindings, "display set");
  createImage(device, display, extent);
  return display;
}

void destroyDisplay(const Device& device, Display& display) {
  destroyImage(device, display);
  destroyDescriptorSet(device, display.descriptors);
  if (display.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(device.handle, display.pipeline, nullptr);
  if (display.pipelineLayout != VK_NULL_HANDLE) vkDestroyPipelineLayout(device.handle, display.pipelineLayout, nullptr);
  if (display.setLayout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device.handle, display.setLayout, nullptr);
  display = {};
}

void resizeDisplay(const Device& device, Display& display, glm::uvec2 extent) {
  destroyImage(device, display);
  createImage(device, display, extent);
}

void bindAccumulation(const Device& device, const Display& display, VkBuffer accumulation) {
  writeStorageBuffer(device, display.descriptors.set, gpu::kBindingDisplayAccumulation, accumulation);
}

void recordClearDisplay(VkCommandBuffer cmd, const Display& display) {
  // UNDEFINED: whatever the image held is discarded, which is the point.
  imageBarrier(cmd, display.image, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, display.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
  imageBarrier(cmd, display.image, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               kRestingLayout);
}

void recordDisplayPass(VkCommandBuffer cmd, const Display& display, glm::uvec2 source, const DisplaySettings& settings,
                       bool keepEmpty) {
  gpu::DisplayParams params{};
  params.sourceSize = source;
  params.targetSize = display.extent;
  params.exposureScale = std::exp2(settings.exposure);
  params.toneMap = toneMapId(settings.toneMap);
  params.flags = (settings.encodeSrgb ? gpu::kDisplayEncodeSrgb : 0u) | (keepEmpty ? gpu::kDisplayKeepEmpty : 0u);
  // After the previous frame's blit (write-after-read); the old layout keeps the texels the pass leaves alone.
  imageBarrier(cmd, display.image, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
               VK_ACCESS_SHADER_WRITE_BIT, kRestingLayout, VK_IMAGE_LAYOUT_GENERAL);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, display.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, display.pipelineLayout, 0, 1, &display.descriptors.set,
                          0, nullptr);
  vkCmdPushConstants(cmd, display.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params, &params);
  vkCmdDispatch(cmd, (display.extent.x + kWorkgroupSize - 1) / kWorkgroupSize,
                (display.extent.y + kWorkgroupSize - 1) / kWorkgroupSize, 1);
  imageBarrier(cmd, display.image, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, kRestingLayout);
}

void recordBlitToSwapchain(VkCommandBuffer cmd, const Display& display, VkImage target, VkExtent2D targetExtent) {
  // The acquire semaphore orders this after the presentation engine's read; UNDEFINED drops the old content.
  imageBarrier(cmd, target, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {static_cast<std::int32_t>(display.extent.x), static_cast<std::int32_t>(display.extent.y), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {static_cast<std::int32_t>(targetExtent.width), static_cast<std::int32_t>(targetExtent.height), 1};
  const bool sameSize = display.extent.x == targetExtent.width && display.extent.y == targetExtent.height;
  vkCmdBlitImage(cmd, display.image, kRestingLayout, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
                 sameSize || !display.linearBlit ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

}  // namespace raylab
