#include "render/wavefront.h"

#include <algorithm>

#include "shared/features.h"
#include "shared/wavefront.h"
#include "util/error.h"
#include "vk/commands.h"

namespace raylab {

namespace {

// FrameParams then WaveParams, as wavefront.comp declares its push constants.
struct WavePush {
  gpu::FrameParams frame;
  gpu::WaveParams wave;
};
static_assert(sizeof(WavePush) == 128, "the wavefront's push constants must fit the 128 bytes every device has");

std::uint32_t groups(std::uint32_t invocations) {
  return (invocations + gpu::kWaveWorkgroupSize - 1) / gpu::kWaveWorkgroupSize;
}

void pushWave(VkCommandBuffer cmd, VkPipelineLayout layout, const WavePush& push) {
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
}

// One wave: `rows` rows of `width` pixels from params.tileOrigin, params.sampleCount samples each.
void recordWave(VkCommandBuffer cmd, const Wavefront& wavefront, VkPipelineLayout layout, const gpu::FrameParams& frame,
                std::uint32_t width, std::uint32_t rows) {
  const std::uint32_t pixels = width * rows;
  gpu::WaveControl control{};
  control.slots = pixels * frame.sampleCount;
  control.capacity = kWaveCapacity;
  vkCmdUpdateBuffer(cmd, wavefront.control.handle, 0, sizeof control, &control);
  computeBarrier(cmd);

  WavePush push{frame, {gpu::kWaveFirstSegment, 0, width}};
  pushWave(cmd, layout, push);
  vkCmdDispatch(cmd, groups(control.slots), 1, 1);
  computeBarrier(cmd);
  // A path has at most maxDepth + 2 segments (docs/integrators.md); a segment dispatch of an empty queue is empty.
  for (std::uint32_t segment = 1; segment < frame.maxDepth + 2; ++segment) {
    push.wave.mode = gpu::kWavePrepare;
    push.wave.queue = (segment - 1) & 1u;
    pushWave(cmd, layout, push);
    vkCmdDispatch(cmd, 1, 1, 1);
    computeBarrier(cmd);
    push.wave.mode = gpu::kWaveSegment;
    push.wave.queue = segment & 1u;
    pushWave(cmd, layout, push);
    vkCmdDispatchIndirect(cmd, wavefront.control.handle,
                          offsetof(gpu::WaveControl, dispatch) + push.wave.queue * 3 * sizeof(std::uint32_t));
    computeBarrier(cmd);
  }
  push.wave.mode = gpu::kWaveAccumulate;
  pushWave(cmd, layout, push);
  vkCmdDispatch(cmd, groups(pixels), 1, 1);
  computeBarrier(cmd);
}

}  // namespace

bool lightEscapes(const Scene& scene) {
  return scene.environment.hasImage() || std::max({scene.background.r, scene.background.g, scene.background.b}) > 0.0f;
}

bool usesWavefront(Schedule schedule, const KernelFeatures& kernel, Backend backend, bool lightEscapes) {
  const bool possible = kernel.integrator == gpu::kIntegratorPath && backend == Backend::kQuery;
  if (schedule == Schedule::kWavefront && !possible) {
    throw Error("--schedule wavefront: only the path integrator on the ray-query backend runs as a wavefront",
                kExitUsage);
  }
  if (schedule != Schedule::kAutomatic) return schedule == Schedule::kWavefront;
  // Measured (docs/performance.md): in closed scenes lit by emitters paths bounce long and unevenly, and the
  // wavefront is 5-15% faster; where light escapes (an environment image, a lit background) most paths leave
  // after a bounce or two, the lanes stay busy anyway, and the megakernel needs 5-20% less CPU time.
  return possible && !lightEscapes;
}

std::vector<DescriptorBinding> wavefrontBindings() {
  return {{gpu::kBindingPathStates, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
          {gpu::kBindingPathResults, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
          {gpu::kBindingPathQueues, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
          {gpu::kBindingWaveControl, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
          {gpu::kBindingPathAovs, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
}

bool hasWavefrontBuffers(const Wavefront& wavefront) { return wavefront.control.handle != VK_NULL_HANDLE; }

void createWavefrontBuffers(const Device& device, Wavefront& wavefront, VkDescriptorSet set) {
  constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  wavefront.states = createBuffer(device, VkDeviceSize(kWaveCapacity) * sizeof(gpu::PathState), kStorage,
                                  MemoryUse::kDevice, "wavefront path states");
  wavefront.results = createBuffer(device, VkDeviceSize(kWaveCapacity) * sizeof(glm::vec4), kStorage,
                                   MemoryUse::kDevice, "wavefront path results");
  wavefront.aovs = createBuffer(device, VkDeviceSize(kWaveCapacity) * 2 * sizeof(glm::vec4), kStorage,
                                MemoryUse::kDevice, "wavefront first-hit albedo and normal");
  wavefront.queues = createBuffer(device, VkDeviceSize(kWaveCapacity) * 2 * sizeof(std::uint32_t), kStorage,
                                  MemoryUse::kDevice, "wavefront queues");
  wavefront.control = createBuffer(device, sizeof(gpu::WaveControl),
                                   kStorage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   MemoryUse::kDevice, "wavefront control");
  writeStorageBuffer(device, set, gpu::kBindingPathStates, wavefront.states.handle);
  writeStorageBuffer(device, set, gpu::kBindingPathResults, wavefront.results.handle);
  writeStorageBuffer(device, set, gpu::kBindingPathQueues, wavefront.queues.handle);
  writeStorageBuffer(device, set, gpu::kBindingPathAovs, wavefront.aovs.handle);
  writeStorageBuffer(device, set, gpu::kBindingWaveControl, wavefront.control.handle);
}

void destroyWavefront(const Device& device, Wavefront& wavefront) {
  destroyBuffer(device, wavefront.control);
  destroyBuffer(device, wavefront.queues);
  destroyBuffer(device, wavefront.aovs);
  destroyBuffer(device, wavefront.results);
  destroyBuffer(device, wavefront.states);
  releasePipeline(device, wavefront.pipeline);
  wavefront = {};
}

void recordWavefrontPass(VkCommandBuffer cmd, const Wavefront& wavefront, VkPipelineLayout layout, VkDescriptorSet set,
                         const gpu::FrameParams& params, glm::uvec2 tileSize) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, wavefront.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
  // Waves of whole rows, and for wide tiles with many samples, of fewer samples at a time: a pixel's samples
  // still reach its sum in order, one chunk of samples after the other.
  const std::uint32_t samplesPerWave = std::min(params.sampleCount, std::max(1u, kWaveCapacity / tileSize.x));
  for (std::uint32_t first = 0; first < params.sampleCount; first += samplesPerWave) {
    gpu::FrameParams frame = params;
    frame.sampleIndex = params.sampleIndex + first;
    frame.sampleCount = std::min(samplesPerWave, params.sampleCount - first);
    const std::uint32_t rowsPerWave = std::max(1u, kWaveCapacity / (tileSize.x * frame.sampleCount));
    for (std::uint32_t row = 0; row < tileSize.y; row += rowsPerWave) {
      gpu::FrameParams wave = frame;
      wave.tileOrigin = params.tileOrigin + glm::uvec2(0, row);
      recordWave(cmd, wavefront, layout, wave, tileSize.x, std::min(rowsPerWave, tileSize.y - row));
    }
  }
}

}  // namespace raylab
