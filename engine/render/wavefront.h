// The path integrator as a wavefront on the ray-query backend (shaders/wavefront.comp): waves of paths that
// advance one segment per dispatch, the paths still alive compacted into a queue between segments, so that no
// lane of lavapipe's 8-lane groups idles while its neighbours finish longer paths. The megakernel stays for the
// slides' integrator, for the pipeline backend and for environment-lit scenes (docs/performance.md: the
// measurements behind the choice).
// The image is bit for bit the megakernel's.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/backend.h"
#include "render/kernel_features.h"
#include "scene/scene.h"
#include "shared/frame.h"
#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace raylab {

// How a render traces its paths: as the wavefront or as the megakernel; `automatic` decides by kernel and backend.
enum class Schedule { kAutomatic, kMegakernel, kWavefront };

// The schedule a kernel runs with: automatically the wavefront for path kernels on ray queries in closed scenes
// (no environment image, a black background: `lightEscapes` false), where it measured faster, the megakernel
// otherwise. Throws Error(kExitUsage) for a wavefront that cannot run (the slides' integrator splits paths at
// glass into a queue of its own; the pipeline backend has no subgroup operations to compact queues with).
bool usesWavefront(Schedule schedule, const KernelFeatures& kernel, Backend backend, bool lightEscapes);

// True when paths that leave the scene see light: an environment image or a background that is not black.
bool lightEscapes(const Scene& scene);

// Paths one wave holds: 2^18 (the buffers take 31 MB).
inline constexpr std::uint32_t kWaveCapacity = 1u << 18;

struct Wavefront {
  VkPipeline pipeline = VK_NULL_HANDLE;  // wavefront.comp, of the renderer's pipeline layout
  Buffer states;   // PathState per slot
  Buffer results;  // vec4 per slot
  Buffer aovs;     // 2 vec4 per slot: the first hit's albedo and normal (kFeatureAovs)
  Buffer queues;   // two queues of slots
  Buffer control;  // WaveControl, also the indirect dispatch arguments
};

// The wavefront's bindings, to merge into the renderer's set layout on the ray-query backend.
std::vector<DescriptorBinding> wavefrontBindings();
// Its buffers, written into `set`; the pipeline is made by the renderer with its own layout.
void createWavefrontBuffers(const Device& device, Wavefront& wavefront, VkDescriptorSet set);
// The pipeline and the buffers.
void destroyWavefront(const Device& device, Wavefront& wavefront);
bool hasWavefrontBuffers(const Wavefront& wavefront);

// Records the samples `params` names (sampleIndex, sampleCount) of the tile [params.tileOrigin,
// params.tileOrigin + tileSize) as waves of at most kWaveCapacity paths, with the pipeline bound to `layout` and
// `set`; each wave ends by adding its samples to the accumulation. Followed by a barrier.
void recordWavefrontPass(VkCommandBuffer cmd, const Wavefront& wavefront, VkPipelineLayout layout, VkDescriptorSet set,
                         const gpu::FrameParams& params, glm::uvec2 tileSize);

}  // namespace raylab
