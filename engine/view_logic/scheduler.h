// Decides what each viewer frame traces, so that a frame stays near its time budget on any device: while the
// view changes, one pass over a reduced-resolution image sized to the budget (the display pass stretches it
// over the window); once nothing has changed for a moment, full-resolution passes of every pixel with
// increasing sample index, split into tiles so that no submission outlasts the budget. After N complete
// full-resolution passes the accumulation holds exactly what `raylab render --spp N` computes: the same RNG
// keys (pixel, sample index, seed) and each pixel's samples added in the same order.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

struct Tile {
  glm::uvec2 origin{0};
  glm::uvec2 size{0};
};

// Tiles of tileSize (multiples of the 8x8 workgroup) covering `extent` row by row; the last row and column
// are cut at the image edge.
std::vector<Tile> makeTiles(glm::uvec2 extent, glm::uvec2 tileSize);

// The rows of a refinement band of about `bandPixels` pixels across `width`: a multiple of 8, at least 8.
std::uint32_t bandRows(std::uint32_t width, std::uint32_t bandPixels);

// Running estimates from the device's timestamps.
struct CostModel {
  double secondsPerPixelSample = 0.0;  // 0 until the first measurement
  double overheadSeconds = 0.0;        // display pass, UI and blit per frame
  std::uint32_t traceMeasurements = 0;
};

// One measurement of `pixelSamples` traced in `seconds`. A sudden outlier (the driver compiling a kernel at
// its first dispatch) moves the estimate by at most a factor of four.
void addTraceMeasurement(CostModel& cost, std::uint64_t pixelSamples, double seconds);
void addOverheadMeasurement(CostModel& cost, double seconds);

struct SchedulerSettings {
  double targetFrameSeconds = 0.050;
  double settleSeconds = 0.25;      // unchanged this long: refine at full resolution
  // Still frames refine in bands of the full width and about this many pixels (a multiple of 8 rows). Lavapipe
  // keeps its threads busy only with enough workgroups: a 640-pixel band of 32 rows traces a pixel-sample in
  // about half the time a 64x64 tile does. Smaller bands pack a frame closer to its budget: bands of 1280x32
  // cost up to 25 ms in the showcase's busy rows, so a 41 ms budget held one of them and idled for the rest.
  std::uint32_t bandPixels = 640 * 32;
  std::uint32_t sppLimit = 0;       // full-resolution passes to stop at; 0: never stop
  float minPreviewScale = 1.0f / 16.0f;
  float firstPreviewScale = 0.25f;  // before anything was measured
};

struct TracePass {
  Tile tile;
  std::uint32_t sampleIndex = 0;
  std::uint32_t tileIndex = 0;  // in Scheduler::tiles of the tiling the plan was made for
};

struct FramePlan {
  bool reset = false;           // clear the accumulation (traceExtent pixels) before the passes
  glm::uvec2 traceExtent{0};    // the resolution the accumulation holds from this frame on
  bool preview = false;         // traceExtent is a reduced resolution
  std::vector<TracePass> passes;
  std::uint64_t pixelSamples = 0;
  std::uint64_t tiling = 0;     // Scheduler::tiling when planned: per-tile times measured for it stay valid
};

enum class FrameKind {
  kInteractive,  // budgeted: preview while moving, tiles of refinement while still
  kUnshown,      // refinement tiles for the whole budget: a still frame that is not displayed (refiningQuietly)
  kFullPass,     // automation: exactly one full-resolution pass (or none past the spp limit)
};

struct Scheduler {
  SchedulerSettings settings;
  CostModel cost;
  glm::uvec2 fullExtent{0};
  // The accumulation's state.
  glm::uvec2 traceExtent{0};
  bool preview = false;
  bool needsReset = true;
  double lastChange = -1.0e30;
  std::vector<Tile> tiles;       // of traceExtent
  // Each tile's last measured device time per pass (0: not measured). Refinement bands differ tenfold in cost
  // (sky against glass), so a frame filled by the mean cost per pixel-sample overruns or idles.
  std::vector<double> tileSeconds;
  std::uint64_t tiling = 0;      // counts restarts: a measurement of an older tiling is stale
  std::size_t nextTile = 0;      // first tile of the pass in progress still to trace
  std::uint32_t sampleIndex = 0; // the pass in progress; also the number of complete passes
};

// One pass of tile `tileIndex` of tiling `tiling` took `seconds` on the device.
void addTileMeasurement(Scheduler& scheduler, std::uint64_t tiling, std::uint32_t tileIndex, double seconds);

// `changed`: the camera, the scene or a render setting changed since the last plan. `now` in seconds.
FramePlan planFrame(Scheduler& scheduler, double now, bool changed, FrameKind kind);

// True when the accumulation is refining at full resolution, still for `settleSeconds`, with nothing changed:
// a frame may then trace without being displayed (FrameKind::kUnshown).
bool refiningQuietly(const Scheduler& scheduler, double now);

// True when a still, full-resolution accumulation has reached the spp limit: there is nothing left to trace.
bool converged(const Scheduler& scheduler);

// The tiles of the accumulation that hold at least one sample (all of them once a pass is complete).
std::vector<Tile> tilesWithSamples(const Scheduler& scheduler);

// Changes the full resolution (window resize, resolution scale): the accumulation is empty, the next plan
// starts over.
void setFullExtent(Scheduler& scheduler, glm::uvec2 extent);

// The reduced resolution that traces in `budgetSeconds` at `secondsPerPixelSample`, with the full image's
// aspect ratio, at least 8 pixels a side and at most the full resolution.
glm::uvec2 previewExtent(glm::uvec2 full, double budgetSeconds, double secondsPerPixelSample, float minScale);

}  // namespace raylab
