// Frames in flight: completing them (timings, ray counts, window captures), recording one (trace passes, the
// display pass, the copy to the window, the UI) and submitting it.
#include "view/viewer_state.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "image/bitmap_text.h"
#include "shared/frame.h"
#include "vk/commands.h"
#include "vk/vk_check.h"

namespace raylab {

void writeWindowCapture(const Viewer& v, const FrameSlot& slot) {
  const std::string& path = v.options.windowCapture;
  const VkExtent2D extent = slot.captureExtent;
  const bool bgra = v.swapchain.format == VK_FORMAT_B8G8R8A8_UNORM || v.swapchain.format == VK_FORMAT_B8G8R8A8_SRGB;
  const auto* pixels = static_cast<const std::uint8_t*>(slot.capture.mapped);
  std::vector<std::uint8_t> rgb(std::size_t(extent.width) * extent.height * 3);
  for (std::size_t i = 0; i < std::size_t(extent.width) * extent.height; ++i) {
    rgb[i * 3 + 0] = pixels[i * 4 + (bgra ? 2 : 0)];
    rgb[i * 3 + 1] = pixels[i * 4 + 1];
    rgb[i * 3 + 2] = pixels[i * 4 + (bgra ? 0 : 2)];
  }
  writePngRgb8(path, extent.width, extent.height, rgb.data());
  if (!v.options.quiet) std::printf("wrote %s\n", path.c_str());
}

void completeFrame(Viewer& v, FrameSlot& slot) {
  const double now = v.clock.seconds();
  const FrameTimes times = readFrameTimes(v.device, slot);
  if (slot.measure) {
    addTraceMeasurement(v.scheduler.cost, slot.pixelSamples, times.traceSeconds);
    const std::vector<double> passSeconds = readPassTimes(v.device, slot);
    for (std::size_t i = 0; i < passSeconds.size(); ++i) {
      addTileMeasurement(v.scheduler, slot.tiling, slot.timedTiles[i], passSeconds[i]);
    }
  }
  // The first frames also compile the display and UI pipelines; an unshown frame has no overhead to measure.
  if (slot.shown && v.report.frames.size() >= kFramesInFlight) {
    addOverheadMeasurement(v.scheduler.cost, times.totalSeconds - times.traceSeconds);
  }
  const auto* stats = static_cast<const gpu::RayStats*>(slot.rayStats.mapped);
  const std::uint64_t rays = std::uint64_t(stats->primaryRays) + stats->shadowRays + stats->secondaryRays;
  v.recentRays.emplace_back(now, rays);
  // Two entries at least, however old: frames slower than the window still give a rate (not "0 rays/s").
  while (v.recentRays.size() > 2 && v.recentRays.front().first < now - kRaysWindow) v.recentRays.pop_front();

  FrameRecord record;
  record.submitSeconds = slot.submitSeconds;
  record.completeSeconds = now;
  record.traceSeconds = times.traceSeconds;
  record.deviceSeconds = times.totalSeconds;
  record.displaySeconds = times.displaySeconds;
  record.blitSeconds = times.blitSeconds;
  record.traceExtent = slot.traceExtent;
  record.preview = slot.preview;
  record.shown = slot.shown;
  record.spp = slot.spp;
  record.pixelSamples = slot.pixelSamples;
  v.report.frames.push_back(record);
  if (slot.captured) writeWindowCapture(v, slot);
  if (slot.differenceRead) readDifferenceStats(v, slot);
  slot.inFlight = false;
  slot.captured = false;
}

void reapFinishedFrames(Viewer& v) {
  for (FrameSlot& slot : v.slots) {
    if (slot.inFlight && vkGetFenceStatus(v.device.handle, slot.fence) == VK_SUCCESS) completeFrame(v, slot);
  }
}

// Blocks until no frame is in flight: before the host writes what frames read (materials, lights) or frees
// what they use (buffers, pipelines, the swapchain).
void waitForFrames(Viewer& v) {
  for (FrameSlot& slot : v.slots) {
    if (!slot.inFlight) continue;
    VK_CHECK(vkWaitForFences(v.device.handle, 1, &slot.fence, VK_TRUE, UINT64_MAX));
    completeFrame(v, slot);
  }
}

bool anyInFlight(const Viewer& v) {
  return std::any_of(v.slots.begin(), v.slots.end(), [](const FrameSlot& slot) { return slot.inFlight; });
}

void recordCapture(VkCommandBuffer cmd, Viewer& v, FrameSlot& slot, VkImage image) {
  const VkExtent2D extent = v.swapchain.extent;
  const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (slot.capture.size < bytes) {
    destroyBuffer(v.device, slot.capture);
    slot.capture = createBuffer(v.device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kHost, "window capture");
  }
  imageBarrier(cmd, image,
               {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.capture.handle, 1, &region);
  computeBarrier(cmd);  // the copy's writes become visible to the host
  imageBarrier(cmd, image,
               {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR});
  slot.captured = true;
  slot.captureExtent = extent;
}

namespace {

// The frame's first commands: the timestamps' reset, the accumulation's clear on a reset, and the plan's trace
// passes, each timed (the scheduler's per-tile costs).
void recordTracePasses(VkCommandBuffer cmd, Viewer& v, FrameSlot& slot, const FramePlan* plan) {
  VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
  vkCmdResetQueryPool(cmd, slot.timestamps, 0, kSlotTimestampCount);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, slot.timestamps, kFrameBegin);
  computeBarrier(cmd);  // after the previous frame's passes and the uploads

  // Both sides of a comparison trace the same passes: the same pixels, sample indices and seed.
  const Renderer* sides[2] = {&v.renderer, v.comparison.active ? &v.comparison.renderer : nullptr};
  if (plan != nullptr && plan->reset) {
    const VkDeviceSize bytes = VkDeviceSize(plan->traceExtent.x) * plan->traceExtent.y * sizeof(glm::vec4);
    for (const Renderer* side : sides) {
      if (side != nullptr) vkCmdFillBuffer(cmd, side->accumulation.handle, 0, bytes, 0);
    }
    computeBarrier(cmd);
  }
  for (const Renderer* side : sides) {
    if (side != nullptr) recordResetRayStats(cmd, *side);
  }
  slot.timedTiles.clear();
  if (plan == nullptr) return;
  slot.tiling = plan->tiling;
  for (const TracePass& pass : plan->passes) {
    const auto timed = std::uint32_t(slot.timedTiles.size());
    if (timed < kTimedPasses) {
      if (timed == 0) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, slot.timestamps, kPassTimestampBase);
      slot.timedTiles.push_back(pass.tileIndex);
    }
    for (const Renderer* side : sides) {
      if (side != nullptr) recordSamplePass(cmd, *side, pass.sampleIndex, pass.tile.origin, pass.tile.size);
    }
    if (timed < kTimedPasses) {
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, slot.timestamps, kPassTimestampBase + timed + 1);
    }
  }
}

// Each tile once: a small image may take several passes in a frame, and unshown frames add theirs.
void addRegion(std::vector<Tile>& regions, const Tile& tile) {
  const bool seen =
      std::any_of(regions.begin(), regions.end(), [&](const Tile& other) { return other.origin == tile.origin; });
  if (!seen) regions.push_back(tile);
}

// Vertically adjacent tiles of the same columns as one: refinement bands traced in order become one dispatch
// and one copy.
std::vector<Tile> mergeBands(std::vector<Tile> tiles) {
  std::sort(tiles.begin(), tiles.end(), [](const Tile& a, const Tile& b) {
    return a.origin.x != b.origin.x ? a.origin.x < b.origin.x : a.origin.y < b.origin.y;
  });
  std::vector<Tile> merged;
  for (const Tile& tile : tiles) {
    if (!merged.empty()) {
      Tile& last = merged.back();
      if (last.origin.x == tile.origin.x && last.size.x == tile.size.x && last.origin.y + last.size.y == tile.origin.y) {
        last.size.y += tile.size.y;
        continue;
      }
    }
    merged.push_back(tile);
  }
  return merged;
}

}  // namespace

void recordUnshownFrame(Viewer& v, FrameSlot& slot, const FramePlan& plan) {
  VkCommandBuffer cmd = slot.cmd;
  recordTracePasses(cmd, v, slot, &plan);
  // No display pass, blit or UI: their timestamps all mark the end of tracing.
  for (const FrameTimestamp stamp : {kTraceEnd, kDisplayEnd, kBlitEnd, kFrameEnd}) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, slot.timestamps, stamp);
  }
  recordCopyRayStats(cmd, v.renderer, slot.rayStats.handle);
  VK_CHECK(vkEndCommandBuffer(cmd));
  for (const TracePass& pass : plan.passes) addRegion(v.undisplayedTiles, pass.tile);
}

void recordFrame(Viewer& v, FrameSlot& slot, const FramePlan* plan, std::uint32_t imageIndex, bool capture,
                 bool readDifference) {
  VkCommandBuffer cmd = slot.cmd;
  recordTracePasses(cmd, v, slot, plan);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, slot.timestamps, kTraceEnd);
  recordCopyRayStats(cmd, v.renderer, slot.rayStats.handle);
  if (readDifference) recordDifferenceReadback(cmd, v, slot);

  // The display pass: the whole preview while moving; while refining only the tiles traced this frame (the
  // refined image keeps its texels), which saves most of the pass at large sizes.
  const glm::uvec2 traced = v.scheduler.traceExtent;
  const DisplaySettings display = displaySettings(v);
  const bool settingsChanged = !(display == v.lastDisplay) || v.pending.display;
  const bool traceDone = plan != nullptr && !plan->passes.empty();
  if (traced.x > 0 && traced.y > 0 && v.scheduler.preview) {
    if (traceDone || settingsChanged || !v.showingPreview) {
      const Tile whole{glm::uvec2(0), traced};
      recordDisplayRegions(cmd, v.display, v.display.preview, traced, display, {&whole, 1});
    }
    v.showingPreview = true;
    v.previewSize = traced;
  } else if (traced.x > 0 && traced.y > 0) {
    if (v.showingPreview) {
      // Refinement starts: the last preview, stretched, stands in for the pixels not traced yet.
      recordPreviewToRefined(cmd, v.display, v.previewSize);
      v.showingPreview = false;
    }
    std::vector<Tile> regions;
    if (settingsChanged) {
      regions = tilesWithSamples(v.scheduler);
    } else {
      regions = v.undisplayedTiles;  // traced by unshown frames since the last display pass
      if (traceDone) {
        for (const TracePass& pass : plan->passes) addRegion(regions, pass.tile);
      }
    }
    recordDisplayRegions(cmd, v.display, v.display.refined, traced, display, mergeBands(regions));
  }
  v.undisplayedTiles.clear();  // shown now, or a preview started over
  v.lastDisplay = display;
  v.pending.display = false;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, slot.timestamps, kDisplayEnd);
  const VkImage image = v.swapchain.images[imageIndex];
  if (v.showingPreview) {
    recordToSwapchain(cmd, v.display, v.display.preview, v.previewSize, image, imageArea(v));
  } else {
    recordToSwapchain(cmd, v.display, v.display.refined, v.display.extent, image, imageArea(v));
  }
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, slot.timestamps, kBlitEnd);
  recordUi(cmd, v.ui, v.swapchain, imageIndex);
  if (capture) recordCapture(cmd, v, slot, image);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps, kFrameEnd);
  VK_CHECK(vkEndCommandBuffer(cmd));
}

void submitUnshown(Viewer& v, FrameSlot& slot) {
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &slot.cmd;
  VK_CHECK(vkResetFences(v.device.handle, 1, &slot.fence));
  VK_CHECK(vkQueueSubmit(v.device.queue, 1, &submit, slot.fence));
  slot.inFlight = true;
}

void submitAndPresent(Viewer& v, FrameSlot& slot, std::uint32_t imageIndex) {
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;  // the blit is the first use of the image
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &slot.imageAvailable;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &slot.cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &v.swapchain.renderFinished[imageIndex];
  VK_CHECK(vkResetFences(v.device.handle, 1, &slot.fence));
  VK_CHECK(vkQueueSubmit(v.device.queue, 1, &submit, slot.fence));
  slot.inFlight = true;

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &v.swapchain.renderFinished[imageIndex];
  present.swapchainCount = 1;
  present.pSwapchains = &v.swapchain.handle;
  present.pImageIndices = &imageIndex;
  const VkResult result = vkQueuePresentKHR(v.device.queue, &present);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) v.pending.swapchain = true;
  else VK_CHECK(result);
}

}  // namespace raylab
