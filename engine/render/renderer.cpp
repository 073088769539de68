#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shared/bindings.h"
#include "shared/features.h"
#include "shared/wavefront.h"
#include "util/error.h"
#include "vk/commands.h"
#include "vk/debug_name.h"
#include "vk/vk_check.h"

namespace raylab {

namespace {

// The render programs, once per backend: render.comp, or the pipeline's raygen, the path
// and shadow miss programs, and closest hit on both hit groups, the triangles' with the alpha test as any-hit
// program (run only on non-opaque geometry), the spheres' with their intersection program.
// Shadow rays, traced from the closest-hit program, are the one level of recursion.
const TracePrograms kRenderPrograms{
    "render.comp", gpu::kRenderWorkgroupSize, gpu::kRenderWorkgroupSize,
    RayTracingProgram{"render.rgen",
                      {"render.rmiss", "shadow.rmiss"},
                      {{"render.rchit", "", "alpha.rahit"}, {"render.rchit", "sphere.rint"}},
                      2}};

SpecializationConstants specializationFor(const KernelFeatures& kernel) {
  SpecializationConstants constants;
  constants.set(gpu::kSpecEnabledModels, kernel.models).set(gpu::kSpecFeatures, kernel.features);
  constants.set(gpu::kSpecGlassFresnel, kernel.schlickFresnel ? gpu::kFresnelSchlick : gpu::kFresnelExact);
  constants.set(gpu::kSpecIntegrator, kernel.integrator);
  constants.set(gpu::kSpecSampling, kernel.sampling);
  constants.set(gpu::kSpecLightKinds, kernel.lightKinds);
  return constants;
}

// The render kernel clocking every pixel (render_heatmap.comp): ray queries, the megakernel.
const TracePrograms kHeatmapPrograms{"render_heatmap.comp", gpu::kRenderWorkgroupSize, gpu::kRenderWorkgroupSize, {}};

// The scene, the accumulation and the counters; on the ray-query backend also the wavefront's buffers, so that
// the render kernel and the wavefront share one layout and one set; with the heat map its clock ticks.
std::vector<DescriptorBinding> rendererBindings(Backend backend, bool heatmap) {
  std::vector<DescriptorBinding> bindings = sceneBindings();
  bindings.push_back({gpu::kBindingAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  bindings.push_back({gpu::kBindingRayStats, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  bindings.push_back({gpu::kBindingAovs, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  for (const DescriptorBinding& binding : pathGuideBindings(backend == Backend::kQuery)) bindings.push_back(binding);
  if (backend == Backend::kQuery) {
    for (const DescriptorBinding& binding : wavefrontBindings()) bindings.push_back(binding);
  }
  if (heatmap) bindings.push_back({gpu::kBindingHeatmap, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  return bindings;
}

// Throws Error naming what is missing when the device or the settings cannot clock pixels.
void checkHeatmap(const Device& device, const RenderSettings& settings) {
  if (!settings.heatmap) return;
  if (!device.shaderClock) {
    throw Error("--heatmap needs VK_KHR_shader_clock's device clock, which " + device.report.name + " lacks",
                kExitNoDevice);
  }
  if (settings.backend != Backend::kQuery) throw Error("--heatmap runs on the ray-query backend only", kExitUsage);
  if (settings.schedule == Schedule::kWavefront) {
    throw Error("--heatmap clocks the megakernel: it cannot run with --schedule wavefront", kExitUsage);
  }
}

// The wavefront pushes WaveParams after FrameParams; the render kernel reads the first part.
std::uint32_t pushConstantBytes(Backend backend) {
  return backend == Backend::kQuery ? sizeof(gpu::FrameParams) + sizeof(gpu::WaveParams) : sizeof(gpu::FrameParams);
}

// Makes the wavefront's buffers the first time a kernel runs as a wavefront.
void prepareWavefront(const Device& device, Renderer& renderer) {
  renderer.wavefrontActive =
      usesWavefront(renderer.schedule, renderer.kernel, renderer.trace.backend, renderer.lightEscapes);
  if (renderer.wavefrontActive && !hasWavefrontBuffers(renderer.wavefront)) {
    createWavefrontBuffers(device, renderer.wavefront, renderer.trace.descriptors.set);
  }
}

// The first-hit images' buffer: 2 vec4 per pixel of the allocated size when the kernel accumulates them, else a
// placeholder the binding points at (the kernel compiles its accesses away). Keeps its contents when its size stays.
void sizeAuxiliaryBuffer(const Device& device, Renderer& renderer, std::uint32_t width, std::uint32_t height) {
  const bool wanted = (renderer.kernel.features & gpu::kFeatureAovs) != 0;
  const VkDeviceSize bytes = wanted ? VkDeviceSize(width) * height * 2 * sizeof(glm::vec4) : sizeof(glm::vec4);
  if (renderer.aovs.handle != VK_NULL_HANDLE && renderer.aovs.size == bytes) return;
  if (bytes > device.properties.limits.maxStorageBufferRange) {
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is too large for the denoiser's albedo and normal images (32 bytes a pixel) on this device",
                kExitUsage);
  }
  destroyBuffer(device, renderer.aovs);
  renderer.aovs = createBuffer(device, bytes,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                   VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               MemoryUse::kDevice, "first-hit albedo and normal");
  writeStorageBuffer(device, renderer.trace.descriptors.set, gpu::kBindingAovs, renderer.aovs.handle);
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, renderer.aovs.handle, 0, VK_WHOLE_SIZE, 0);
    computeBarrier(cmd);
  });
}

}  // namespace

std::uint64_t maxImagePixels(const Device& device) {
  // Also below 2^27 pixels: lavapipe crashes inside the kernel above that whatever the buffer limit says.
  return std::min<std::uint64_t>(device.properties.limits.maxStorageBufferRange / sizeof(glm::vec4),
                                 (std::uint64_t(1) << 27) - 1);
}

void checkImageSize(const Device& device, std::uint32_t width, std::uint32_t height) {
  if (width == 0 || height == 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
                    std::to_string(kMaxImageSide),
                kExitUsage);
  }
  const std::uint64_t pixels = std::uint64_t(width) * height;
  const std::uint64_t limit = maxImagePixels(device);
  if (pixels > limit) {
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " (" + std::to_string(pixels) +
                    " pixels) is over this device's limit of " + std::to_string(limit) +
                    " pixels: the accumulation buffer (16 bytes a pixel) must fit maxStorageBufferRange (" +
                    std::to_string(device.properties.limits.maxStorageBufferRange) +
                    " bytes); lower --width/--height (3840x2160 fits on lavapipe)",
                kExitUsage);
  }
}

namespace {
void fillRenderer(const Device& device, const GpuScene& gpuScene, const Scene& scene, const RenderSettings& settings,
                  Renderer& renderer);
}  // namespace

Renderer createRenderer(const Device& device, const GpuScene& gpuScene, const Scene& scene,
                        const RenderSettings& settings) {
  checkImageSize(device, settings.width, settings.height);
  // The Renderer owns what is created into it: a failure at any step releases everything made before it.
  Renderer renderer;
  try {
    fillRenderer(device, gpuScene, scene, settings, renderer);
  } catch (...) {
    destroyRenderer(device, renderer);
    throw;
  }
  return renderer;
}

namespace {

void fillRenderer(const Device& device, const GpuScene& gpuScene, const Scene& scene, const RenderSettings& settings,
                  Renderer& renderer) {
  gpu::FrameParams& params = renderer.params;
  params.width = settings.width;
  params.height = settings.height;
  params.seed = settings.seed;
  params.background = scene.background;
  params.maxDepth = settings.maxDepth;
  params.lightCount = gpuScene.lightCount;
  params.punctualLightCount = gpuScene.punctualLightCount;
  params.environmentStrength = scene.environment.strength;
  params.environmentRotation = scene.environment.rotation;
  params.flags = settings.jitter ? gpu::kFrameJitter : 0u;
  params.throughputCutoff = settings.throughputCutoff;
  applyCamera(params, scene.camera, settings.width, settings.height);

  renderer.kernel = settings.kernel.value_or(featuresOf(scene));
  if (settings.aovs) renderer.kernel.features |= gpu::kFeatureAovs;
  if (settings.guiding != Guiding::kOff) {
    if (renderer.kernel.integrator != gpu::kIntegratorPath) {
      throw Error("--guiding guides the path integrator's continuations: use it with --integrator path (this render "
                  "runs the slides' integrator, which samples no continuations)",
                  kExitUsage);
    }
    renderer.kernel.features |= gpu::kFeatureGuiding;
  }
  checkHeatmap(device, settings);
  // The heat map clocks each pixel's lane, so it keeps every pixel's samples in the megakernel.
  renderer.schedule = settings.heatmap ? Schedule::kMegakernel : settings.schedule;
  renderer.lightEscapes = lightEscapes(scene);
  // Refuses an impossible --schedule before anything is built.
  usesWavefront(renderer.schedule, renderer.kernel, settings.backend, renderer.lightEscapes);
  renderer.trace = createTraceKernel(device, settings.backend, settings.heatmap ? kHeatmapPrograms : kRenderPrograms,
                                     rendererBindings(settings.backend, settings.heatmap),
                                     pushConstantBytes(settings.backend), gpuScene);

  renderer.stats = createBuffer(device, sizeof(gpu::RayStats),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,  // recordCopyRayStats
                                MemoryUse::kHost, "ray stats");

  writeSceneDescriptors(device, renderer.trace.descriptors.set, gpuScene);
  createPathGuide(device, renderer.guide, scene, settings.guiding, std::uint64_t(settings.width) * settings.height,
                  settings.backend == Backend::kQuery ? kWaveCapacity : 0, renderer.trace.descriptors.set);
  writeStorageBuffer(device, renderer.trace.descriptors.set, gpu::kBindingRayStats, renderer.stats.handle);
  swapRenderPipelines(device, renderer, createRenderPipelines(device, renderer, renderer.kernel), renderer.kernel);
  renderer.clocksPixels = settings.heatmap;  // resizeRenderer sizes the heat map with the accumulation
  resizeRenderer(device, renderer, settings.width, settings.height);
}

}  // namespace

RenderPipelines createRenderPipelines(const Device& device, const Renderer& renderer, const KernelFeatures& kernel) {
  SpecializationConstants constants = specializationFor(kernel);
  RenderPipelines pipelines;
  // Only the one the schedule runs: on lavapipe creating a pipeline costs about 0.3 s of SPIR-V translation
  // and optimisation (Mesa's disk cache keeps only the LLVM compilation of its first dispatch); one created
  // before on this device is found in its store (vk/pipeline_store.h).
  if (usesWavefront(renderer.schedule, kernel, renderer.trace.backend, renderer.lightEscapes)) {
    pipelines.wavefront = acquireComputePipeline(device, renderer.trace.pipelineLayout, "wavefront.comp", &constants);
  } else {
    pipelines.trace = acquireTracePipeline(device, renderer.trace, &constants);
  }
  return pipelines;
}

void destroyRenderPipelines(const Device& device, RenderPipelines& pipelines) {
  releasePipeline(device, pipelines.trace);
  releasePipeline(device, pipelines.wavefront);
  pipelines = {};
}

void swapRenderPipelines(const Device& device, Renderer& renderer, RenderPipelines pipelines,
                         const KernelFeatures& kernel) {
  replaceTracePipeline(device, renderer.trace, pipelines.trace);
  releasePipeline(device, renderer.wavefront.pipeline);
  renderer.wavefront.pipeline = pipelines.wavefront;
  renderer.kernel = kernel;
  prepareWavefront(device, renderer);
  // A kernel that starts or stops accumulating the first-hit images (the viewer's denoiser switch) needs their buffer
  // sized to match; the caller resets the accumulation after a swap.
  if (renderer.accumulation.handle != VK_NULL_HANDLE) {
    sizeAuxiliaryBuffer(device, renderer, renderer.allocatedWidth, renderer.allocatedHeight);
  }
}

void setTraceExtent(Renderer& renderer, glm::uvec2 extent) {
  renderer.params.width = extent.x;
  renderer.params.height = extent.y;
}

void setMaxDepth(Renderer& renderer, std::uint32_t maxDepth) { renderer.params.maxDepth = maxDepth; }

void setSceneLighting(Renderer& renderer, const Scene& scene) {
  renderer.params.background = scene.background;
  renderer.params.environmentStrength = scene.environment.strength;
  renderer.params.environmentRotation = scene.environment.rotation;
}

void setCamera(Renderer& renderer, const Camera& camera) {
  applyCamera(renderer.params, camera, renderer.params.width, renderer.params.height);
}

void resizeRenderer(const Device& device, Renderer& renderer, std::uint32_t width, std::uint32_t height) {
  checkImageSize(device, width, height);
  destroyBuffer(device, renderer.accumulation);
  renderer.accumulation = createBuffer(device, VkDeviceSize(width) * height * sizeof(glm::vec4),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                           VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                       MemoryUse::kDevice, "accumulation");
  writeStorageBuffer(device, renderer.trace.descriptors.set, gpu::kBindingAccumulation, renderer.accumulation.handle);
  renderer.allocatedWidth = width;
  renderer.allocatedHeight = height;
  sizeAuxiliaryBuffer(device, renderer, width, height);
  if (renderer.clocksPixels) {
    destroyBuffer(device, renderer.heatmap);
    renderer.heatmap = createBuffer(device, VkDeviceSize(width) * height * sizeof(float),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    MemoryUse::kDevice, "heat map");
    writeStorageBuffer(device, renderer.trace.descriptors.set, gpu::kBindingHeatmap, renderer.heatmap.handle);
  }
  // The camera's aspect ratio follows the image.
  const float oldAspect = float(renderer.params.width) / float(renderer.params.height);
  const float newAspect = float(width) / float(height);
  renderer.params.cameraRight *= newAspect / oldAspect;
  renderer.params.width = width;
  renderer.params.height = height;
  resetAccumulation(device, renderer);
}

void destroyRenderer(const Device& device, Renderer& renderer) {
  destroyBuffer(device, renderer.heatmap);
  destroyBuffer(device, renderer.stats);
  destroyBuffer(device, renderer.accumulation);
  destroyBuffer(device, renderer.aovs);
  destroyPathGuide(device, renderer.guide);
  destroyWavefront(device, renderer.wavefront);
  destroyTraceKernel(device, renderer.trace);
  renderer = {};
}

void resetAccumulation(const Device& device, Renderer& renderer) {
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, renderer.accumulation.handle, 0, VK_WHOLE_SIZE, 0);
    if (renderer.heatmap.handle != VK_NULL_HANDLE) vkCmdFillBuffer(cmd, renderer.heatmap.handle, 0, VK_WHOLE_SIZE, 0);
    if (renderer.aovs.handle != VK_NULL_HANDLE) vkCmdFillBuffer(cmd, renderer.aovs.handle, 0, VK_WHOLE_SIZE, 0);
    computeBarrier(cmd);
  });
  renderer.samplesDone = 0;
  resetPathGuide(renderer.guide);
}

namespace {

// Upper bound of the rays one sample of every pixel can trace; keeps the 32-bit ray counters from wrapping.
std::uint64_t maxRaysPerSample(const gpu::FrameParams& params) {
  // Per vertex: the continuation, and a shadow ray per punctual light (slides) or one (path).
  const std::uint64_t perPath = std::uint64_t(params.maxDepth + 1) * (2 + params.punctualLightCount);
  return std::uint64_t(params.width) * params.height * perPath;
}

// Small images spread over too few workgroups to keep lavapipe's threads busy: a 64x64 image traced one
// sample per dispatch costs 2.5x more per pixel than a 512x512 one. Several samples per dispatch up to about
// this many pixel-samples restore the balance (the image is the same: samples are summed in order anyway).
constexpr std::uint64_t kPixelSamplesPerDispatch = 1u << 19;

void submitSamples(const Device& device, Renderer& renderer, std::uint32_t samples) {
  const glm::uvec2 size(renderer.params.width, renderer.params.height);
  const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
  const auto perDispatch = static_cast<std::uint32_t>(std::clamp<std::uint64_t>(kPixelSamplesPerDispatch / pixels, 1, samples));
  submitAndWait(device, [&](VkCommandBuffer cmd) {
    recordResetRayStats(cmd, renderer);
    for (std::uint32_t done = 0; done < samples; done += perDispatch) {
      recordSamplePass(cmd, renderer, renderer.samplesDone + done, glm::uvec2(0), size,
                       std::min(perDispatch, samples - done));
    }
  });
  renderer.samplesDone += samples;
  collectRayStats(renderer);
}

}  // namespace

void renderSamples(const Device& device, Renderer& renderer, std::uint32_t samples) {
  const std::uint64_t perSubmission =
      std::max<std::uint64_t>(1, (std::uint64_t(1) << 31) / std::max<std::uint64_t>(1, maxRaysPerSample(renderer.params)));
  while (samples > 0) {
    auto batch = static_cast<std::uint32_t>(std::min<std::uint64_t>(samples, perSubmission));
    const bool guideUpdates = guideWantsUpdate(renderer.guide, renderer.samplesDone);
    if (guideUpdates) batch = std::min(batch, renderer.guide.nextUpdate - renderer.samplesDone);
    submitSamples(device, renderer, batch);
    samples -= batch;
    if (guideUpdates && renderer.samplesDone >= renderer.guide.nextUpdate) {
      updatePathGuide(renderer.guide, renderer.samplesDone);
    }
  }
}

void recordSamplePass(VkCommandBuffer cmd, const Renderer& renderer, std::uint32_t sampleIndex,
                      glm::uvec2 tileOrigin, glm::uvec2 tileSize, std::uint32_t sampleCount) {
  gpu::FrameParams params = renderer.params;
  params.sampleIndex = sampleIndex;
  params.sampleCount = sampleCount;
  params.tileOrigin = tileOrigin;
  if (renderer.wavefrontActive) {
    const glm::uvec2 size(params.width, params.height);
    recordWavefrontPass(cmd, renderer.wavefront, renderer.trace.pipelineLayout, renderer.trace.descriptors.set, params,
                        glm::min(tileSize, size - glm::min(tileOrigin, size)));
    return;
  }
  // The push constants the layout declares: FrameParams, and on the ray-query backend room for WaveParams.
  struct {
    gpu::FrameParams frame;
    gpu::WaveParams wave;
  } push{params, {}};
  recordTrace(cmd, renderer.trace, &push, tileSize.x, tileSize.y);
  computeBarrier(cmd);  // the next pass reads and adds to the same sums
}

void recordResetRayStats(VkCommandBuffer cmd, const Renderer& renderer) {
  vkCmdFillBuffer(cmd, renderer.stats.handle, 0, VK_WHOLE_SIZE, 0);
  computeBarrier(cmd);
}

void recordCopyRayStats(VkCommandBuffer cmd, const Renderer& renderer, VkBuffer destination) {
  const VkBufferCopy region{0, 0, sizeof(gpu::RayStats)};
  vkCmdCopyBuffer(cmd, renderer.stats.handle, destination, 1, &region);
  computeBarrier(cmd);
}

void collectRayStats(Renderer& renderer) {
  const auto* stats = static_cast<const gpu::RayStats*>(renderer.stats.mapped);
  renderer.rays.primary += stats->primaryRays;
  renderer.rays.shadow += stats->shadowRays;
  renderer.rays.secondary += stats->secondaryRays;
  renderer.droppedSamples += stats->droppedSamples;
  renderer.rays.laneSegments += stats->laneSegments;
  renderer.rays.groupSegments += stats->groupSegments;
}

double laneUtilisation(const RayCounts& rays, std::uint32_t subgroupSize) {
  return rays.groupSegments > 0 ? double(rays.laneSegments) / (double(subgroupSize) * double(rays.groupSegments)) : 0.0;
}

Image readImage(const Device& device, const Renderer& renderer) {
  Image image(renderer.params.width, renderer.params.height);
  downloadBuffer(device, renderer.accumulation, image.rgba.data(), image.rgba.size() * sizeof(float));
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const float count = image.rgba[i + 3];
    const float scale = count > 0.0f ? 1.0f / count : 0.0f;
    for (int c = 0; c < 3; ++c) image.rgba[i + c] *= scale;
    image.rgba[i + 3] = 1.0f;
  }
  return image;
}

bool hasAuxiliaryImages(const Renderer& renderer) { return (renderer.kernel.features & gpu::kFeatureAovs) != 0; }

AuxiliaryImages readAuxiliaryImages(const Device& device, const Renderer& renderer) {
  if (!hasAuxiliaryImages(renderer)) {
    throw Error("readAuxiliaryImages: the renderer's kernel does not accumulate first-hit albedo and normal");
  }
  const std::uint32_t width = renderer.params.width, height = renderer.params.height;
  const std::size_t pixels = std::size_t(width) * height;
  // The traced extent is the top-left part of the allocation, rows `width` long: the kernel indexes it so.
  std::vector<glm::vec4> counts(pixels), sums(2 * pixels);
  downloadBuffer(device, renderer.accumulation, counts.data(), pixels * sizeof(glm::vec4));
  downloadBuffer(device, renderer.aovs, sums.data(), 2 * pixels * sizeof(glm::vec4));
  AuxiliaryImages images{Image(width, height), Image(width, height)};
  for (std::size_t i = 0; i < pixels; ++i) {
    const float scale = counts[i].w > 0.0f ? 1.0f / counts[i].w : 0.0f;
    const glm::vec3 albedo = glm::clamp(glm::vec3(sums[2 * i]) * scale, 0.0f, 1.0f);
    const glm::vec3 normal = glm::vec3(sums[2 * i + 1]) * scale;
    std::copy_n(&albedo.x, 3, &images.albedo.rgba[4 * i]);
    std::copy_n(&normal.x, 3, &images.normal.rgba[4 * i]);
    images.albedo.rgba[4 * i + 3] = 1.0f;
    images.normal.rgba[4 * i + 3] = 1.0f;
  }
  return images;
}

PixelValue readPixel(const Device& device, const Renderer& renderer, glm::uvec2 pixel) {
  if (pixel.x >= renderer.params.width || pixel.y >= renderer.params.height) {
    throw Error("readPixel: pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) +
                ") is outside the traced " + std::to_string(renderer.params.width) + "x" +
                std::to_string(renderer.params.height));
  }
  glm::vec4 texel(0.0f);
  const VkDeviceSize index = VkDeviceSize(pixel.y) * renderer.params.width + pixel.x;
  downloadBuffer(device, renderer.accumulation, &texel, sizeof texel, index * sizeof texel);
  PixelValue value;
  value.samples = static_cast<std::uint32_t>(texel.w);
  if (texel.w > 0.0f) value.radiance = glm::vec3(texel) / texel.w;
  return value;
}

CostMap readCostMap(const Device& device, const Renderer& renderer) {
  if (renderer.heatmap.handle == VK_NULL_HANDLE) throw Error("readCostMap: the renderer was made without the heat map");
  CostMap map;
  map.width = renderer.params.width;
  map.height = renderer.params.height;
  map.ticks.resize(std::size_t(map.width) * map.height);
  // Already per sample: the least over the render's dispatches (render_heatmap.comp).
  downloadBuffer(device, renderer.heatmap, map.ticks.data(), map.ticks.size() * sizeof(float));
  return map;
}

}  // namespace raylab
