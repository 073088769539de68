#include "view_logic/scheduler.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// Weights of a new measurement in the running estimates: a slowdown (the view turned to costlier content)
// must shrink the preview within a frame or two, a speedup may take its time.
constexpr double kSmoothingUp = 0.6;
constexpr double kSmoothingDown = 0.25;
constexpr float kHysteresis = 0.12f;  // a preview may grow only by more than 12%, so its size does not flicker
constexpr double kMinTraceShare = 0.25;  // tracing gets at least this share of the frame, whatever the overhead
// A fast device on a small window could fit thousands of passes in a budget: more per frame gain nothing.
constexpr std::uint32_t kMaxPassesPerFrame = 16;

double traceBudget(const Scheduler& s) {
  const double target = s.settings.targetFrameSeconds;
  return std::max(target - s.cost.overheadSeconds, kMinTraceShare * target);
}

bool refining(const Scheduler& s) { return !s.needsReset && !s.preview && s.traceExtent == s.fullExtent; }

void restart(Scheduler& s, glm::uvec2 extent, bool preview, FramePlan& plan) {
  s.traceExtent = extent;
  s.preview = preview;
  // A preview pass is traced whole in one frame: one dispatch is cheaper than many.
  s.tiles = preview ? std::vector<Tile>{{{0, 0}, extent}} : makeTiles(extent, {extent.x, bandRows(extent.x, s.settings.bandPixels)});
  s.tileSeconds.assign(s.tiles.size(), 0.0);
  ++s.tiling;
  s.nextTile = 0;
  s.sampleIndex = 0;
  s.needsReset = false;
  plan.reset = true;
}

void addPass(FramePlan& plan, const Tile& tile, std::uint32_t sampleIndex, std::size_t tileIndex) {
  plan.passes.push_back({tile, sampleIndex, std::uint32_t(tileIndex)});
  plan.pixelSamples += std::uint64_t(tile.size.x) * tile.size.y;
}

bool limitReached(const Scheduler& s) { return s.settings.sppLimit > 0 && s.sampleIndex >= s.settings.sppLimit; }

// Takes tiles of the pass in progress (and the next passes) until `budget` is used; at least one tile.
void addTiles(Scheduler& s, FramePlan& plan, double budget) {
  double spent = 0.0;
  const std::uint32_t lastSample = s.sampleIndex + kMaxPassesPerFrame;
  while (!limitReached(s) && s.sampleIndex < lastSample) {
    const Tile& tile = s.tiles[s.nextTile];
    const double measured = s.tileSeconds[s.nextTile];
    const double cost = measured > 0.0 ? measured : double(tile.size.x) * tile.size.y * s.cost.secondsPerPixelSample;
    if (!plan.passes.empty() && spent + cost > budget) break;
    addPass(plan, tile, s.sampleIndex, s.nextTile);
    spent += cost;
    if (++s.nextTile == s.tiles.size()) {
      s.nextTile = 0;
      ++s.sampleIndex;
    }
    // Nothing measured yet: one tile, to measure it.
    if (s.cost.secondsPerPixelSample <= 0.0) break;
  }
}

}  // namespace

std::vector<Tile> makeTiles(glm::uvec2 extent, glm::uvec2 tileSize) {
  std::vector<Tile> tiles;
  for (std::uint32_t y = 0; y < extent.y; y += tileSize.y) {
    for (std::uint32_t x = 0; x < extent.x; x += tileSize.x) {
      tiles.push_back({{x, y}, {std::min(tileSize.x, extent.x - x), std::min(tileSize.y, extent.y - y)}});
    }
  }
  return tiles;
}

std::uint32_t bandRows(std::uint32_t width, std::uint32_t bandPixels) {
  return std::max(8u, bandPixels / std::max(width, 1u) / 8u * 8u);
}

void addTraceMeasurement(CostModel& cost, std::uint64_t pixelSamples, double seconds) {
  if (pixelSamples == 0 || !(seconds > 0.0)) return;
  double sample = seconds / double(pixelSamples);
  if (cost.traceMeasurements == 0) {
    cost.secondsPerPixelSample = sample;
  } else {
    const double current = cost.secondsPerPixelSample;
    sample = std::clamp(sample, 0.25 * current, 4.0 * current);
    const double weight = sample > current ? kSmoothingUp : kSmoothingDown;
    cost.secondsPerPixelSample = (1.0 - weight) * current + weight * sample;
  }
  ++cost.traceMeasurements;
}

void addTileMeasurement(Scheduler& s, std::uint64_t tiling, std::uint32_t tileIndex, double seconds) {
  if (tiling != s.tiling || tileIndex >= s.tileSeconds.size() || !(seconds > 0.0)) return;
  double& current = s.tileSeconds[tileIndex];
  // As the running estimate: a kernel compiled at its first dispatch must not poison a tile for good.
  if (current > 0.0) seconds = std::clamp(seconds, 0.25 * current, 4.0 * current);
  const double weight = current == 0.0 ? 1.0 : seconds > current ? kSmoothingUp : kSmoothingDown;
  current = (1.0 - weight) * current + weight * seconds;
}

void addOverheadMeasurement(CostModel& cost, double seconds) {
  if (!(seconds >= 0.0)) return;
  const double weight = seconds > cost.overheadSeconds ? kSmoothingUp : kSmoothingDown;
  cost.overheadSeconds =
      cost.overheadSeconds == 0.0 ? seconds : (1.0 - weight) * cost.overheadSeconds + weight * seconds;
}

glm::uvec2 previewExtent(glm::uvec2 full, double budgetSeconds, double secondsPerPixelSample, float minScale) {
  const double pixels = budgetSeconds / secondsPerPixelSample;
  const double scale = std::clamp(std::sqrt(pixels / (double(full.x) * full.y)), double(minScale), 1.0);
  return {std::clamp(std::uint32_t(std::lround(full.x * scale)), std::min(8u, full.x), full.x),
          std::clamp(std::uint32_t(std::lround(full.y * scale)), std::min(8u, full.y), full.y)};
}

void setFullExtent(Scheduler& scheduler, glm::uvec2 extent) {
  scheduler.fullExtent = extent;
  scheduler.needsReset = true;
  // Nothing of the old size survives: the accumulation was reallocated, and an old preview size might not fit.
  scheduler.traceExtent = glm::uvec2(0);
  scheduler.preview = false;
  scheduler.tiles.clear();
  scheduler.tileSeconds.clear();
  ++scheduler.tiling;
  scheduler.nextTile = 0;
  scheduler.sampleIndex = 0;
}

std::vector<Tile> tilesWithSamples(const Scheduler& s) {
  if (s.sampleIndex > 0) return s.tiles;
  return std::vector<Tile>(s.tiles.begin(), s.tiles.begin() + std::ptrdiff_t(s.nextTile));
}

bool converged(const Scheduler& s) { return refining(s) && limitReached(s); }

bool refiningQuietly(const Scheduler& s, double now) {
  return refining(s) && !limitReached(s) && now - s.lastChange >= s.settings.settleSeconds;
}

FramePlan planFrame(Scheduler& s, double now, bool changed, FrameKind kind) {
  FramePlan plan;
  if (changed) {
    s.lastChange = now;
    s.needsReset = true;
  }
  const bool moving = kind != FrameKind::kFullPass && now - s.lastChange < s.settings.settleSeconds;

  if (moving) {
    if (s.needsReset || !s.preview) {
      glm::uvec2 extent = s.fullExtent;
      if (s.cost.secondsPerPixelSample > 0.0) {
        extent = previewExtent(s.fullExtent, traceBudget(s), s.cost.secondsPerPixelSample, s.settings.minPreviewScale);
      } else {
        extent = glm::max(glm::uvec2(glm::vec2(s.fullExtent) * s.settings.firstPreviewScale), glm::uvec2(8));
        extent = glm::min(extent, s.fullExtent);
      }
      // Small swings of the estimate should not make the preview's size flicker; shrinking is never delayed.
      const bool slightlyLarger =
          extent.x >= s.traceExtent.x && float(extent.x) < (1.0f + kHysteresis) * float(s.traceExtent.x);
      if (s.preview && slightlyLarger) extent = s.traceExtent;
      restart(s, extent, true, plan);
    }
    // The preview is sized so that one whole pass fits the budget: the window always shows a complete image.
    for (std::size_t i = 0; i < s.tiles.size(); ++i) addPass(plan, s.tiles[i], s.sampleIndex, i);
    ++s.sampleIndex;
  } else {
    if (s.needsReset || s.preview || s.traceExtent != s.fullExtent) restart(s, s.fullExtent, false, plan);
    if (kind == FrameKind::kFullPass) {
      if (!limitReached(s)) {
        for (std::size_t i = s.nextTile; i < s.tiles.size(); ++i) addPass(plan, s.tiles[i], s.sampleIndex, i);
        s.nextTile = 0;
        ++s.sampleIndex;
      }
    } else {
      // An unshown frame has no display pass, blit, UI or presentation: its whole budget traces.
      addTiles(s, plan, kind == FrameKind::kUnshown ? s.settings.targetFrameSeconds : traceBudget(s));
    }
  }
  plan.traceExtent = s.traceExtent;
  plan.preview = s.preview;
  plan.tiling = s.tiling;
  return plan;
}

}  // namespace raylab
