// What one frame in flight owns: its command buffer, the fence the main thread polls instead of waiting, the
// acquire semaphore, timestamps around the trace passes (the scheduler's cost model), a copy of the ray
// counters, and read-back buffers for window captures and the comparison's difference statistics.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "vk/device.h"
#include "vk/resources.h"

namespace raylab {

// Timestamp queries of a frame.
enum FrameTimestamp : std::uint32_t {
  kFrameBegin = 0,
  kTraceEnd = 1,
  kDisplayEnd = 2,
  kBlitEnd = 3,
  kFrameEnd = 4,
  kFrameTimestampCount = 5,
};
// Timestamps between the trace passes of a frame (one before the first, one after each), after the frame's
// own: each pass's device time, for the scheduler's per-tile costs. Passes beyond the first kTimedPasses of a
// frame (a small image takes many) go untimed.
constexpr std::uint32_t kTimedPasses = 32;
constexpr std::uint32_t kPassTimestampBase = kFrameTimestampCount;
constexpr std::uint32_t kSlotTimestampCount = kPassTimestampBase + kTimedPasses + 1;

struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;  // signalled: the slot is free
  VkSemaphore imageAvailable = VK_NULL_HANDLE;
  VkQueryPool timestamps = VK_NULL_HANDLE;
  Buffer rayStats;     // RayStats after this frame's passes
  Buffer capture;      // swapchain pixels, when the frame captured the window
  Buffer difference;   // both sides' accumulated sums, when the frame read them for the difference statistics
  bool inFlight = false;

  // What the submitted frame did, read back when it completes.
  double submitSeconds = 0.0;
  std::uint64_t pixelSamples = 0;
  glm::uvec2 traceExtent{0};
  bool preview = false;
  bool shown = true;
  std::uint32_t spp = 0;
  bool measure = false;   // its timings may feed the cost model (not a kernel's first dispatch)
  std::vector<std::uint32_t> timedTiles;  // the scheduler's tile index of each timed pass
  std::uint64_t tiling = 0;               // the scheduler's tiling they index
  bool captured = false;
  VkExtent2D captureExtent{};
  bool differenceRead = false;
  glm::uvec2 differenceExtent{0};
};

FrameSlot createFrameSlot(const Device& device);
void destroyFrameSlot(const Device& device, FrameSlot& slot);

struct FrameTimes {
  double traceSeconds = 0.0;    // trace passes on the device
  double displaySeconds = 0.0;  // the display pass
  double blitSeconds = 0.0;     // the blit to the swapchain image
  double totalSeconds = 0.0;    // the whole command buffer on the device (the UI is the rest)
};
FrameTimes readFrameTimes(const Device& device, const FrameSlot& slot);
// The device time of each timed pass, in order.
std::vector<double> readPassTimes(const Device& device, const FrameSlot& slot);

}  // namespace raylab
