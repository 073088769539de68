// Path guiding's host side (kernel/guiding.glsl, shared/guiding.h): the grid over the scene, the training sums the
// kernel adds to, and the per-cell distributions rebuilt from them after 1, 2, 4, ... samples per pixel until the
// training budget is spent. `auto` keeps guiding only when the second moment it measured under the guide beats BSDF
// sampling's by a margin (docs/integrators.md, "Path guiding").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shared/guiding.h"
#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace raylab {

// --guiding: off, on (every cell with a distribution), auto (where it measured a gain). Order of kGuidingValues.
enum class Guiding { kOff, kOn, kAuto };

// Samples per pixel over which the guide trains (rebuilt after 1, 2, 4, ... of them); later samples use the last
// distributions and add nothing to them.
inline constexpr std::uint32_t kGuideTrainingSamples = 64;
// The share of a guided cell's continuations drawn from its distribution (Mueller et al. 2017 use one half).
inline constexpr float kGuideProbability = 0.5f;

struct PathGuideSummary {
  std::uint32_t updates = 0;      // distributions rebuilt so far
  std::uint32_t cellsGuided = 0;  // cells with a distribution
  // `auto`: whether the trial is over, BSDF sampling's second moment over the guide's mixture's it measured, and
  // whether guiding goes on.
  bool decided = false;
  double momentRatio = 0.0;
  bool guiding = true;
};

struct PathGuide {
  Guiding mode = Guiding::kOff;
  Buffer guide;     // GuideHeader and the cumulative distributions, host-visible: rewritten between submissions
  Buffer training;  // the kernel's fixed-point sums, host-visible: read and zeroed at each update
  Buffer trails;    // the wavefront's per-slot training vertices (a placeholder when there is no wavefront)
  gpu::GuideHeader header{};
  std::vector<double> radiance;  // per cell and bin: the sum over every update so far
  std::vector<double> samples;   // per cell: vertices recorded
  // `auto`'s trial, every cell's: BSDF sampling's second moment and the guide's mixture's (guide_training.glsl).
  double momentBsdf = 0.0;
  double momentMixture = 0.0;
  std::uint32_t nextUpdate = 1;  // samples per pixel after which the distributions are rebuilt next
  PathGuideSummary summary;
};

// The most cells the grid of an image of `pixels` pixels has (at most gpu::kGuideCells).
std::uint32_t guideCellBudget(std::uint64_t pixels);
// The grid over the scene's bounds, sized for an image of `pixels`, and the buffers, written into `set` (bindings
// kBindingGuide, kBindingGuideTraining, and kBindingGuideTrails when `wavefrontSlots` > 0). With Guiding::kOff,
// placeholders the kernel never reads.
void createPathGuide(const Device& device, PathGuide& guide, const Scene& scene, Guiding mode, std::uint64_t pixels,
                     std::uint32_t wavefrontSlots, VkDescriptorSet set);
void destroyPathGuide(const Device& device, PathGuide& guide);
// Forgets everything learned: the next samples train from nothing (a new image).
void resetPathGuide(PathGuide& guide);
// True when the samples after `samplesDone` per pixel should stop at `nextUpdate` for an update.
bool guideWantsUpdate(const PathGuide& guide, std::uint32_t samplesDone);
// After the device finished the samples up to `samplesDone` per pixel: takes in their training sums and rebuilds
// the distributions (and the verdicts of `auto`); stops training once kGuideTrainingSamples are done.
void updatePathGuide(PathGuide& guide, std::uint32_t samplesDone);

// "path guiding (auto): 1234 cells, 7 updates over the first 64 spp; trial: BSDF sampling's second moment 1.8x the
// guide's, guiding on" (what `raylab render` prints).
std::string describeGuide(const PathGuide& guide);

// The bindings of the guide, for the renderer's set layout (the trails only with a wavefront).
std::vector<DescriptorBinding> pathGuideBindings(bool withTrails);

}  // namespace raylab
