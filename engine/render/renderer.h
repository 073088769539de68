// The offscreen renderer: the render kernel (render.comp with ray queries, or render.rgen and its programs in a
// ray-tracing pipeline) over a GpuScene, accumulating samples per pixel into a float32 buffer. `raylab render`,
// the viewer and the image tests all drive this.
#pragma once

#include <cstdint>
#include <optional>

#include "image/heatmap.h"
#include "image/image.h"
#include "render/backend.h"
#include "render/kernel_features.h"
#include "render/path_guide.h"
#include "render/trace_kernel.h"
#include "render/wavefront.h"
#include "scene/camera_frame.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"
#include "shared/frame.h"
#include "vk/device.h"
#include "util/render_options.h"
#include "vk/resources.h"

namespace raylab {


struct RenderSettings {
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  std::uint32_t maxDepth = kMaxDepthOption.defaultValue;  // bounces after the primary hit
  std::uint32_t seed = 0;
  bool jitter = true;                 // anti-aliasing by jittered sub-pixel samples; off: pixel centres
  float throughputCutoff = 1.0e-3f;   // paths whose weight falls below this stop
  std::optional<KernelFeatures> kernel;  // the kernel variant; default: exactly what the scene uses
  Backend backend = Backend::kQuery;     // chooseBackend picks it for the device
  Schedule schedule = Schedule::kAutomatic;  // the wavefront for path kernels on ray queries (usesWavefront)
  bool heatmap = false;  // clock every pixel (render_heatmap.comp: the megakernel on ray queries, needs shaderClock)
  bool aovs = false;     // also accumulate the first-hit albedo and normal images for the denoiser (kFeatureAovs)
  Guiding guiding = Guiding::kOff;  // path guiding (kFeatureGuiding, render/path_guide.h): the path integrator only
};

struct RayCounts {
  std::uint64_t primary = 0;
  std::uint64_t shadow = 0;
  std::uint64_t secondary = 0;
  std::uint64_t total() const { return primary + shadow + secondary; }
  // Lane utilisation of the ray-query backend (gpu::RayStats); both 0 on the pipeline backend.
  std::uint64_t laneSegments = 0;
  std::uint64_t groupSegments = 0;
};

// The share of its groups' segment slots the lanes used (lavapipe runs 8 lanes in lockstep, so a group runs until
// its busiest lane is done); 0 when it was not measured.
double laneUtilisation(const RayCounts& rays, std::uint32_t subgroupSize);

struct Renderer {
  TraceKernel trace;    // the render programs on the chosen backend, specialised for `kernel`
  Wavefront wavefront;  // the ray-query backend's wavefront.comp, of trace's layout; buffers while it is in use
  Schedule schedule = Schedule::kAutomatic;
  bool lightEscapes = false;     // of the scene, for the automatic schedule
  bool wavefrontActive = false;  // usesWavefront(schedule, kernel, backend, lightEscapes)
  bool clocksPixels = false;     // settings.heatmap
  Buffer heatmap;                // float clock ticks per pixel, when clocksPixels
  Buffer accumulation;  // vec4 per pixel: radiance sum and sample count
  std::uint32_t allocatedWidth = 0;  // the accumulation's size (resizeRenderer); the traced extent may be less
  std::uint32_t allocatedHeight = 0;
  Buffer aovs;          // 2 vec4 per pixel with kFeatureAovs: first-hit albedo and normal sums; else one placeholder
  Buffer stats;         // RayStats per submission, host-visible
  PathGuide guide;      // with RenderSettings.guiding; reset with the accumulation
  KernelFeatures kernel;  // what the pipeline was specialised for
  gpu::FrameParams params{};
  std::uint32_t samplesDone = 0;
  RayCounts rays;
  std::uint64_t droppedSamples = 0;  // NaN or Inf samples the kernel left out (0 on every committed scene)
};

// The most pixels an image may have on `device`: its accumulation buffer must fit one storage-buffer binding.
std::uint64_t maxImagePixels(const Device& device);
// Throws Error(kExitUsage) naming the size and the limit when `device` cannot render width x height.
void checkImageSize(const Device& device, std::uint32_t width, std::uint32_t height);

// Creates the pipeline on settings.backend (LLVM compiles it on lavapipe at the first dispatch, not here).
Renderer createRenderer(const Device& device, const GpuScene& gpuScene, const Scene& scene,
                        const RenderSettings& settings);
void destroyRenderer(const Device& device, Renderer& renderer);

// Adds `samples` samples to every pixel (in as few submissions as the 32-bit ray counters allow, and while a path
// guide trains, ending one at each of its updates).
void renderSamples(const Device& device, Renderer& renderer, std::uint32_t samples);

// Records `sampleCount` samples (RNG sample indices sampleIndex, sampleIndex + 1, ...) of every pixel of the
// tile [tileOrigin, tileOrigin + tileSize), followed by a barrier. tileOrigin and tileSize must be multiples
// of 8 (the compute workgroup), except where the tile ends at the image edge, so that tiles never overlap.
// For callers that schedule their own submissions (the viewer); renderSamples does it all for offscreen work.
void recordSamplePass(VkCommandBuffer cmd, const Renderer& renderer, std::uint32_t sampleIndex,
                      glm::uvec2 tileOrigin, glm::uvec2 tileSize, std::uint32_t sampleCount = 1);
// Ray counters: zero them at the start of a submission, add them to renderer.rays after it completed.
void recordResetRayStats(VkCommandBuffer cmd, const Renderer& renderer);
void collectRayStats(Renderer& renderer);
// Copies the counters into `destination` (a RayStats-sized transfer-destination buffer) and makes them visible
// to the host: for callers with several submissions in flight, each reading its own copy (the viewer).
void recordCopyRayStats(VkCommandBuffer cmd, const Renderer& renderer, VkBuffer destination);

// Live changes (the viewer). Each leaves the accumulated samples stale: reset them afterwards.
// The traced extent: at most the allocated size (resizeRenderer), the top-left part of the accumulation; the
// camera keeps the aspect ratio of the extent (call setCamera after it).
void setTraceExtent(Renderer& renderer, glm::uvec2 extent);
void setCamera(Renderer& renderer, const Camera& camera);
void setMaxDepth(Renderer& renderer, std::uint32_t maxDepth);
// The scene's lighting parameters the kernel reads per dispatch: background, environment strength and rotation.
void setSceneLighting(Renderer& renderer, const Scene& scene);
// New image size: reallocates the accumulation buffer (and resets it). Throws Error(kExitUsage) beyond
// kMaxImageSide or maxImagePixels, leaving the renderer as it was.
void resizeRenderer(const Device& device, Renderer& renderer, std::uint32_t width, std::uint32_t height);
// The pipelines of a kernel variant: the render programs, and on the ray-query backend the wavefront.
struct RenderPipelines {
  VkPipeline trace = VK_NULL_HANDLE;
  VkPipeline wavefront = VK_NULL_HANDLE;
};
// The pipelines of the renderer's layout and backend specialised for `kernel`; thread-safe, for building them in
// the background. On lavapipe the driver compiles them at their first dispatch, not here.
RenderPipelines createRenderPipelines(const Device& device, const Renderer& renderer, const KernelFeatures& kernel);
void destroyRenderPipelines(const Device& device, RenderPipelines& pipelines);
// Replaces the pipelines (the old ones are destroyed: the device must not be using them), the pipeline backend's
// shader binding table with them, and makes the wavefront's buffers if the new kernel runs as a wavefront.
void swapRenderPipelines(const Device& device, Renderer& renderer, RenderPipelines pipelines,
                         const KernelFeatures& kernel);

// Clears the accumulated samples (after a camera or parameter change).
void resetAccumulation(const Device& device, Renderer& renderer);

// The mean radiance per pixel so far, alpha 1.
Image readImage(const Device& device, const Renderer& renderer);

// The first-hit albedo and normal images (kernel/aov.glsl) of the samples so far, divided by the same counts as the
// radiance; albedo clamped to [0, 1]. Throws Error when the kernel was not made with them (RenderSettings.aovs, or
// kFeatureAovs in the kernel features).
AuxiliaryImages readAuxiliaryImages(const Device& device, const Renderer& renderer);
bool hasAuxiliaryImages(const Renderer& renderer);

// One pixel of the traced extent: its mean radiance and how many samples it holds (the viewer's picking).
struct PixelValue {
  glm::vec3 radiance{0.0f};
  std::uint32_t samples = 0;
};
PixelValue readPixel(const Device& device, const Renderer& renderer, glm::uvec2 pixel);

// With settings.heatmap: clock ticks per sample of every pixel so far.
CostMap readCostMap(const Device& device, const Renderer& renderer);

}  // namespace raylab
