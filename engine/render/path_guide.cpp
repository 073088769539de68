#include "render/path_guide.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "scene/camera_pivot.h"
#include "shared/features.h"
#include "util/render_options.h"

namespace raylab {

namespace {

// A cell builds a distribution once this many vertices recorded what came back through them: fewer leave most of
// its 256 bins empty by chance, and the guide would send samples only where a few happened to go.
constexpr double kMinCellSamples = 64.0;
// The histogram's share of a cell's distribution; the rest is uniform, so that no direction the training missed
// has a density near zero under the guide (the BSDF's half of the mixture covers it too).
constexpr double kHistogramShare = 0.9;
// `auto` renders its trial (the samples up to kAutoTrialSamples) with BSDF sampling alone while the guide trains,
// and guides the rest only when the second moment the guide's mixture would have had, estimated from the same
// samples (kernel/guide_training.glsl), is at most 1 / kAutoGain of BSDF sampling's: the margin pays for the
// guide's cost per sample, about 20% on lavapipe (docs/performance.md, "Path guiding").
constexpr std::uint32_t kAutoTrialSamples = 16;
constexpr double kAutoGain = 1.25;

constexpr std::size_t kCells = gpu::kGuideCells;
// Cells per pixel of the image: the training's samples per cell grow with the image, and a cell with too few learns
// noise (measured on glossy_room at 320x180, 128 spp: the variance under guiding fell from 0.047 with 16384 cells to
// 0.034 with 4096 and 0.033 with 1024, against 0.071 unguided).
constexpr std::uint64_t kPixelsPerCell = 16;
constexpr std::uint64_t kMinCellBudget = 512;
constexpr std::size_t kBins = gpu::kGuideBins;

Buffer createHostBuffer(const Device& device, VkDeviceSize bytes, const char* name) {
  Buffer buffer = createBuffer(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::kHost, name);
  std::memset(buffer.mapped, 0, bytes);
  return buffer;
}

float* distributions(PathGuide& guide) {
  return reinterpret_cast<float*>(static_cast<char*>(guide.guide.mapped) + sizeof(gpu::GuideHeader));
}

void writeHeader(PathGuide& guide) { std::memcpy(guide.guide.mapped, &guide.header, sizeof guide.header); }

// The training word `word` (64-bit, low word first) as the sum it holds in units of 1/scale.
double trainingValue(const std::uint32_t* words, std::size_t word, double scale) {
  const std::uint64_t value = std::uint64_t(words[2 * word]) | (std::uint64_t(words[2 * word + 1]) << 32);
  return double(value) / scale;
}

// The cell's cumulative distribution from its radiance sums: the histogram mixed with a uniform share.
void buildDistribution(const double* radiance, float* cdf) {
  double total = 0.0;
  for (std::size_t b = 0; b < kBins; ++b) total += radiance[b];
  double running = 0.0;
  for (std::size_t b = 0; b < kBins; ++b) {
    running += kHistogramShare * radiance[b] / total + (1.0 - kHistogramShare) / double(kBins);
    cdf[b] = float(running);
  }
  cdf[kBins - 1] = 1.0f;
}

}  // namespace

std::string describeGuide(const PathGuide& guide) {
  const PathGuideSummary& g = guide.summary;
  char text[256];
  const std::string mode(kGuidingValues[std::size_t(guide.mode)]);
  const int n = std::snprintf(text, sizeof text, "path guiding (%s): %u cells, %u updates over the first %u spp",
                              mode.c_str(), g.cellsGuided, g.updates, kGuideTrainingSamples);
  if (guide.mode == Guiding::kAuto && g.decided && n > 0) {
    std::snprintf(text + n, sizeof text - n, "; trial: BSDF sampling's second moment %.2fx the guided one's, guiding %s",
                  g.momentRatio, g.guiding ? "on" : "off");
  }
  return text;
}

std::vector<DescriptorBinding> pathGuideBindings(bool withTrails) {
  std::vector<DescriptorBinding> bindings = {{gpu::kBindingGuide, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                             {gpu::kBindingGuideTraining, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  if (withTrails) bindings.push_back({gpu::kBindingGuideTrails, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  return bindings;
}

std::uint32_t guideCellBudget(std::uint64_t pixels) {
  return std::uint32_t(std::clamp<std::uint64_t>(pixels / kPixelsPerCell, kMinCellBudget, kCells));
}

void createPathGuide(const Device& device, PathGuide& guide, const Scene& scene, Guiding mode, std::uint64_t pixels,
                     std::uint32_t wavefrontSlots, VkDescriptorSet set) {
  guide.mode = mode;
  const bool on = mode != Guiding::kOff;
  guide.guide = createHostBuffer(device, sizeof(gpu::GuideHeader) + (on ? kCells * kBins * sizeof(float) : 16),
                                 "path guide distributions");
  guide.training = createHostBuffer(device, on ? kCells * gpu::kGuideTrainingWords * 2 * sizeof(std::uint32_t) : 16,
                                    "path guide training sums");
  writeStorageBuffer(device, set, gpu::kBindingGuide, guide.guide.handle);
  writeStorageBuffer(device, set, gpu::kBindingGuideTraining, guide.training.handle);
  if (wavefrontSlots > 0) {
    const VkDeviceSize trailBytes =
        on ? VkDeviceSize(wavefrontSlots) * gpu::kGuideTrailLength * sizeof(gpu::GuideRecord) : 16;
    guide.trails = createBuffer(device, trailBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::kDevice,
                                "path guide trails");
    writeStorageBuffer(device, set, gpu::kBindingGuideTrails, guide.trails.handle);
  }
  // The grid spans the scene's bounds, enlarged a little so that points on the boundary fall inside, in cubes as
  // small as the cell budget allows.
  const SceneBounds bounds = sceneBounds(scene);
  const glm::vec3 rawExtent = bounds.high - bounds.low;
  const glm::vec3 margin = glm::vec3(0.01f * std::max(std::max({rawExtent.x, rawExtent.y, rawExtent.z}), 1e-3f));
  const glm::dvec3 extent = glm::dvec3(rawExtent + 2.0f * margin);
  const double budget = double(guideCellBudget(pixels));
  double side = std::cbrt(extent.x * extent.y * extent.z / budget);
  glm::uvec3 size;
  for (;; side *= 1.02) {  // the cube root ignores the rounding up of each axis: grow until they fit
    size = glm::uvec3(glm::max(glm::ceil(extent / side), glm::dvec3(1.0)));
    if (double(size.x) * size.y * size.z <= budget) break;
  }
  guide.header.gridMin = bounds.low - margin;
  guide.header.gridSize = size;
  guide.header.cellScale = float(1.0 / side);
  guide.header.guideProbability = kGuideProbability;
  resetPathGuide(guide);
}

void destroyPathGuide(const Device& device, PathGuide& guide) {
  destroyBuffer(device, guide.trails);
  destroyBuffer(device, guide.training);
  destroyBuffer(device, guide.guide);
  guide = {};
}

void resetPathGuide(PathGuide& guide) {
  if (guide.guide.mapped == nullptr) return;
  const bool on = guide.mode != Guiding::kOff;
  guide.header.mode = !on ? 0u : guide.mode == Guiding::kAuto ? gpu::kGuideTraining | gpu::kGuideTrial
                                                               : gpu::kGuideTraining;
  writeHeader(guide);
  if (!on) return;
  std::fill_n(distributions(guide), kCells * kBins, 0.0f);
  std::memset(guide.training.mapped, 0, guide.training.size);
  guide.radiance.assign(kCells * kBins, 0.0);
  guide.samples.assign(kCells, 0.0);
  guide.momentBsdf = 0.0;
  guide.momentMixture = 0.0;
  guide.nextUpdate = 1;
  guide.summary = {};
  guide.summary.guiding = guide.mode == Guiding::kOn;  // `auto` renders its trial unguided
}

bool guideWantsUpdate(const PathGuide& guide, std::uint32_t samplesDone) {
  return (guide.header.mode & gpu::kGuideTraining) != 0 && samplesDone < guide.nextUpdate;
}

void updatePathGuide(PathGuide& guide, std::uint32_t samplesDone) {
  if ((guide.header.mode & gpu::kGuideTraining) == 0) return;
  const auto* words = static_cast<const std::uint32_t*>(guide.training.mapped);
  // `auto`'s trial: the pass's second moments, BSDF sampling's as drawn and the guide's mixture's had it drawn.
  if ((guide.header.mode & gpu::kGuideTrial) != 0) {
    for (std::size_t cell = 0; cell < kCells; ++cell) {
      const std::size_t base = cell * gpu::kGuideTrainingWords;
      guide.momentBsdf += trainingValue(words, base + gpu::kGuideMomentWord, gpu::kGuideMomentScale);
      guide.momentMixture += trainingValue(words, base + gpu::kGuideMixtureMomentWord, gpu::kGuideMomentScale);
    }
  }
  float* cdfs = distributions(guide);
  PathGuideSummary summary = guide.summary;
  summary.updates += 1;
  summary.cellsGuided = 0;
  for (std::size_t cell = 0; cell < kCells; ++cell) {
    const std::size_t base = cell * gpu::kGuideTrainingWords;
    double* radiance = &guide.radiance[cell * kBins];
    double total = 0.0;
    for (std::size_t b = 0; b < kBins; ++b) {
      radiance[b] += trainingValue(words, base + b, gpu::kGuideRadianceScale);
      total += radiance[b];
    }
    guide.samples[cell] += trainingValue(words, base + gpu::kGuideCountWord, 1.0);
    if (guide.samples[cell] >= kMinCellSamples && total > 0.0) {
      buildDistribution(radiance, &cdfs[cell * kBins]);
      summary.cellsGuided += 1;
    }
  }
  std::memset(guide.training.mapped, 0, guide.training.size);
  // `on` guides from the first update; `auto` only after its trial, and only where the mixture would have cut the
  // continuations' second moment by kAutoGain.
  if (guide.mode == Guiding::kOn) guide.header.mode |= gpu::kGuideSampling;
  if (guide.mode == Guiding::kAuto && !summary.decided && samplesDone >= kAutoTrialSamples) {
    summary.decided = true;
    summary.momentRatio = guide.momentMixture > 0.0 ? guide.momentBsdf / guide.momentMixture : 0.0;
    summary.guiding = summary.momentRatio >= kAutoGain;
    guide.header.mode = summary.guiding ? (gpu::kGuideTraining | gpu::kGuideSampling) : 0u;
  }
  while (guide.nextUpdate <= samplesDone) guide.nextUpdate *= 2;
  if (samplesDone >= kGuideTrainingSamples) guide.header.mode &= ~gpu::kGuideTraining;
  guide.summary = summary;
  writeHeader(guide);
}

}  // namespace raylab
