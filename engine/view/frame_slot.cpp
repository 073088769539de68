#include <cstdio>
#include <cstdlib>
#include "view/frame_slot.h"

#include "shared/frame.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

FrameSlot createFrameSlot(const Device& device) {
  FrameSlot slot;
  VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocateInfo.commandPool = device.commandPool;
  allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocateInfo.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocateInfo, &slot.cmd));
  setDebugName(device, VK_OBJECT_TYPE_COMMAND_BUFFER, reinterpret_cast<std::uint64_t>(slot.cmd), "frame commands");

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VK_CHECK(vkCreateFence(device.handle, &fenceInfo, nullptr, &slot.fence));
  setDebugName(device, VK_OBJECT_TYPE_FENCE, reinterpret_cast<std::uint64_t>(slot.fence), "frame done");

  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vkCreateSemaphore(device.handle, &semaphoreInfo, nullptr, &slot.imageAvailable));
  setDebugName(device, VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<std::uint64_t>(slot.imageAvailable),
               "image available");

  VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
  queryInfo.queryCount = kSlotTimestampCount;
  VK_CHECK(vkCreateQueryPool(device.handle, &queryInfo, nullptr, &slot.timestamps));
  setDebugName(device, VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<std::uint64_t>(slot.timestamps), "frame timestamps");

  slot.rayStats = createBuffer(device, sizeof(gpu::RayStats), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::kHost,
                               "frame ray stats");
  return slot;
}

void destroyFrameSlot(const Device& device, FrameSlot& slot) {
  destroyBuffer(device, slot.capture);
  destroyBuffer(device, slot.difference);
  destroyBuffer(device, slot.rayStats);
  if (slot.timestamps != VK_NULL_HANDLE) vkDestroyQueryPool(device.handle, slot.timestamps, nullptr);
  if (slot.imageAvailable != VK_NULL_HANDLE) vkDestroySemaphore(device.handle, slot.imageAvailable, nullptr);
  if (slot.fence != VK_NULL_HANDLE) vkDestroyFence(device.handle, slot.fence, nullptr);
  if (slot.cmd != VK_NULL_HANDLE) vkFreeCommandBuffers(device.handle, device.commandPool, 1, &slot.cmd);
  slot = {};
}

FrameTimes readFrameTimes(const Device& device, const FrameSlot& slot) {
  std::uint64_t ticks[kFrameTimestampCount] = {};
  VK_CHECK(vkGetQueryPoolResults(device.handle, slot.timestamps, 0, kFrameTimestampCount, sizeof ticks, ticks,
                                 sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT));
  const double period = device.properties.limits.timestampPeriod * 1.0e-9;
  FrameTimes times;
  times.traceSeconds = double(ticks[kTraceEnd] - ticks[kFrameBegin]) * period;
  times.displaySeconds = double(ticks[kDisplayEnd] - ticks[kTraceEnd]) * period;
  times.blitSeconds = double(ticks[kBlitEnd] - ticks[kDisplayEnd]) * period;
  times.totalSeconds = double(ticks[kFrameEnd] - ticks[kFrameBegin]) * period;
  return times;
}

}  // namespace raylab

namespace raylab {

std::vector<double> readPassTimes(const Device& device, const FrameSlot& slot) {
  const auto count = std::uint32_t(slot.timedTiles.size());
  if (count == 0) return {};
  std::uint64_t ticks[kTimedPasses + 1] = {};
  VK_CHECK(vkGetQueryPoolResults(device.handle, slot.timestamps, kPassTimestampBase, count + 1,
                                 sizeof(std::uint64_t) * (count + 1), ticks, sizeof(std::uint64_t),
                                 VK_QUERY_RESULT_64_BIT));
  const double period = device.properties.limits.timestampPeriod * 1.0e-9;
  std::vector<double> seconds(count);
  for (std::uint32_t i = 0; i < count; ++i) seconds[i] = double(ticks[i + 1] - ticks[i]) * period;
  return seconds;
}

}  // namespace raylab
