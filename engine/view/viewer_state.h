// The viewer's state and the steps its files share (engine/view/viewer_*.cpp): set-up and tear-down, frames in
// flight and their recording, edits from the panel, scripts and hot keys, and kernel rebuilds. Internal to
// engine/view.
//
// What must be redone before the next frame is explicit in `Pending` below: each flag names the events that set it
// and the step that clears it. The kernel's state (ready, building in the background, or compiling at its first
// dispatch) is `KernelState`.
#pragma once

#include <array>
#include <deque>
#include <future>
#include <memory>
#include <string>

#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "util/timer.h"
#include "view/camera_input.h"
#include "view/compare_ui.h"
#include "view/comparison.h"
#include "view/display.h"
#include "view/frame_slot.h"
#include "view/kernel_build.h"
#include "view/lobe_plot.h"
#include "view/slice_plot.h"
#include "view/panel.h"
#include "view/swapchain.h"
#include "view/ui.h"
#include "view/viewer.h"
#include "view/window.h"
#include "view_logic/camera_controller.h"
#include "view_logic/pointer.h"
#include "view_logic/scheduler.h"

namespace raylab {

constexpr std::uint32_t kFramesInFlight = 2;
constexpr std::uint64_t kPollNanoseconds = 2'000'000;  // a fence wait never keeps input waiting longer
constexpr int kUiSettleFrames = 3;     // frames drawn after an input event while idle (ImGui hover states)
constexpr double kResizeTimeout = 5.0;  // seconds a scripted resize may take
constexpr double kRaysWindow = 1.0;     // rays/s over this many seconds of frames
constexpr double kIdleWaitSeconds = 0.5;    // idle: the status line still refreshes this often
constexpr double kBuildPollSeconds = 0.05;  // a kernel build's end is noticed within this
constexpr double kDifferenceSeconds = 1.0;  // the difference statistics are measured at most this often
// While refining with no input, a frame is displayed at least this often and the frames between only trace:
// each displayed frame costs its display pass, blit, UI and lavapipe's copy to the window (about 15 ms of a
// 50 ms frame at 1280x720), and the device idles while the host copies.
constexpr double kRefineDisplaySeconds = 0.25;
constexpr double kHoverSeconds = 0.1;       // the hovered material is cast for at most this often
constexpr std::uint64_t kHoverTriangles = 200'000;  // above this the CPU cast is too slow for hovering

// Set by events, cleared by the step named: the viewer's state machine.
struct Pending {
  bool accumulation = true;  // camera, material, light, integrator, depth or size changed: planFrame resets it
  bool swapchain = false;    // acquire or present said out of date or suboptimal: recreateSwapchain
  bool extent = false;       // resolution scale changed, panel shown or hidden: updateFullExtent
  bool display = true;       // the display images were cleared or the tone settings changed: the next display pass
                             // covers every tile
};

// The denoised view (viewer_denoise.cpp): the last result shown in place of the accumulation, and the job making the
// next one.
struct DenoisedView {
  std::future<Image> job;          // Open Image Denoise on its own thread
  std::uint64_t jobGeneration = 0;  // the view the job's image belongs to
  std::uint32_t jobSamples = 0;
  double jobStartSeconds = 0.0;
  std::uint64_t generation = 0;     // bumped whenever the accumulation restarts
  std::uint32_t nextSamples = 1;    // the samples per pixel at which the still image is denoised next
  bool showing = false;             // the display pass reads `shown`
  std::uint32_t shownSamples = 0;
  Buffer shown;                     // the denoised image as an accumulation of one sample per pixel
  Image image;                      // the same on the host, for screenshots
};

enum class KernelState {
  kReady,         // the pipeline has run: frame timings measure tracing
  kFirstDispatch,  // a new pipeline: its next dispatch compiles (lavapipe), so that frame is not timed
};

struct Viewer {
  Viewer(const Scene& s, const ViewerOptions& o) : options(o), scene(s), panelShown(o.panel) {}

  const ViewerOptions& options;
  Scene scene;  // edited live by the panel and the script
  bool panelShown = true;  // the panel's strip beside the image (F1 toggles it)
  std::uint32_t integrator = chooseIntegrator(scene, options.integrator);
  bool windowSystem = false;
  Instance instance;
  Window window;
  Device device;
  GpuScene gpuScene;
  Renderer renderer;
  Swapchain swapchain;
  Display display;
  Ui ui;
  std::array<FrameSlot, kFramesInFlight> slots;

  Scheduler scheduler;
  CameraController controller;
  CursorTracker cameraCursor;
  Camera camera;
  ViewSettings settings;
  PanelStatus status;
  PanelSelection selection;
  std::unique_ptr<KernelBuild> build;
  KernelFeatures needed;      // what the scene's materials and lights need compiled in
  KernelState kernelState = KernelState::kFirstDispatch;
  Pending pending;
  std::vector<Tile> undisplayedTiles;  // refined by unshown frames, for the next display pass
  double lastShown = -1.0e30;          // when the last displayed frame was submitted
  DisplaySettings lastDisplay;
  bool showingPreview = false;  // the window shows the preview image (else the refined one)
  glm::uvec2 previewSize{0};
  bool automation = false;
  std::uint32_t frameIndex = 0;       // frames submitted
  std::int64_t eventsAppliedFor = -1;  // the frame whose script events were applied
  std::uint32_t lastScriptFrame = 0;
  int uiFramesLeft = kUiSettleFrames;
  Stopwatch clock;
  double lastSubmit = -1.0;
  double lastCameraUpdate = 0.0;
  double frameMs = 0.0;
  std::deque<std::pair<double, std::uint64_t>> recentRays;  // (completion time, rays of that frame)
  ViewerReport report;

  // The comparison (viewer_compare.cpp): the right side, how it shows, and the mouse over the image.
  Comparison comparison;
  gpu::MaterialRecord comparedRecord{};  // the panel's copy of comparison.spec.record
  CompareView compareView;
  DifferenceStats difference;
  double lastDifference = -kDifferenceSeconds;
  PointerState pointer;
  glm::vec2 cursor{0.0f};
  std::optional<PickedPixel> picked;
  std::string hovered;  // the material under the cursor
  glm::vec2 hoveredAt{-1.0f};
  double lastHover = 0.0;
  LobePlot lobe;
  std::optional<SlicePlot> slicePlot;  // --target
  DenoisedView denoised;
};

// viewer_setup.cpp
glm::uvec2 fullExtentFor(VkExtent2D window, float scale, std::uint64_t maxPixels);
KernelFeatures neededKernel(const Viewer& v);
VkRect2D imageArea(const Viewer& v);
void setUp(Viewer& v);
void tearDown(Viewer& v);
void updateFullExtent(Viewer& v);
void recreateSwapchain(Viewer& v);

// viewer_frames.cpp
void completeFrame(Viewer& v, FrameSlot& slot);
void reapFinishedFrames(Viewer& v);
// Blocks until no frame is in flight: before the host writes what frames read (materials, lights) or frees
// what they use (buffers, pipelines, the swapchain).
void waitForFrames(Viewer& v);
bool anyInFlight(const Viewer& v);
void recordFrame(Viewer& v, FrameSlot& slot, const FramePlan* plan, std::uint32_t imageIndex, bool capture,
                 bool readDifference);
void submitAndPresent(Viewer& v, FrameSlot& slot, std::uint32_t imageIndex);
// A refinement frame that is not displayed: trace passes only (viewer.cpp, drawUnshownFrame).
void recordUnshownFrame(Viewer& v, FrameSlot& slot, const FramePlan& plan);
void submitUnshown(Viewer& v, FrameSlot& slot);

// viewer_edits.cpp
std::string timestampedScreenshotPath();
void saveScreenshot(Viewer& v, const std::string& exrPath, const std::string& pngPath);
void uploadSceneEdits(Viewer& v, bool materials, bool lights);
void applyScriptEvents(Viewer& v);
void handleHotKeys(Viewer& v, const WindowInput& input);
void updateStatus(Viewer& v);

// viewer_kernels.cpp
bool covers(const KernelFeatures& kernel, const KernelFeatures& needed);
void installKernel(Viewer& v);
void ensureKernel(Viewer& v);
void switchIntegrator(Viewer& v);

// viewer_denoise.cpp
// True when the image shown may be denoised: the switch is on and nothing is compared.
bool denoiseApplies(const Viewer& v);
// Turns the denoised view on or off (a kernel with the albedo and normal images builds in the background); a missing
// Open Image Denoise leaves it off with the reason in the status.
void setDenoise(Viewer& v, bool on);
// Takes a finished denoise, and starts the next when the still image reached its sample count: once per loop.
void updateDenoise(Viewer& v);
// The accumulation restarts: the denoised image no longer matches it. `rebind` points the display pass back at the
// accumulation (updateFullExtent rebinds it itself).
void discardDenoised(Viewer& v, bool rebind);
// With --exit-at-limit the viewer waits for the denoised image of the converged one: true when it is shown, or when
// nothing is denoised.
bool denoisedToTheLimit(const Viewer& v);
// What the status line says about denoising; empty with the switch off.
std::string denoiseStatus(const Viewer& v);
void destroyDenoisedView(Viewer& v);

// viewer_compare.cpp
void startComparing(Viewer& v, const CompareSpec& spec);
void stopComparing(Viewer& v);
// After the scene's materials or the integrator changed: the right side follows (the device idle).
void refreshComparison(Viewer& v);
// The mouse over the image: divider drags, clicks (picking) and hovering; true while the camera must stay still.
bool handlePointer(Viewer& v);
// Selects the material under `fraction` of the image and reads that pixel of both sides.
void pickAt(Viewer& v, glm::vec2 fraction);
// The panel's Compare, Picked pixel and Lobe sections.
void drawComparisonSections(Viewer& v);
void drawOverlay(Viewer& v);
// The difference statistics, without stalling the frames: a frame that is due copies both sides' sums into its
// slot after its trace passes, and the statistics are computed when that frame completes.
bool differenceStatsDue(const Viewer& v);
void recordDifferenceReadback(VkCommandBuffer cmd, Viewer& v, FrameSlot& slot);
void readDifferenceStats(Viewer& v, FrameSlot& slot);
DisplaySettings displaySettings(const Viewer& v);
// With a comparison, FILE_compare.exr (the right side) and FILE_difference.exr (|A - B|) beside a screenshot.
void saveComparison(Viewer& v, const std::string& exrPath);
void saveLobe(Viewer& v, const std::string& path);
void applyCompareEvent(Viewer& v, const ScriptEvent& event);

}  // namespace raylab
