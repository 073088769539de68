// The viewer's logic that needs no window: the frame scheduler (tiles, budgets, the preview size, the
// deterministic passes that make the viewer's image equal `raylab render`'s), the script parser and the camera
// operations.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "brdf_params/material_params.h"
#include "scene/gltf_test_support.h"
#include "scene/scene.h"
#include "util/error.h"
#include "view_logic/camera_controller.h"
#include "view_logic/scheduler.h"
#include "view_logic/script.h"

namespace raylab::test {
namespace {

// Per pixel, the sample indices it received, in order.
using SampleLog = std::vector<std::vector<std::uint32_t>>;

void logPlan(const FramePlan& plan, glm::uvec2 extent, SampleLog& log) {
  if (plan.reset) log.assign(std::size_t(extent.x) * extent.y, {});
  for (const TracePass& pass : plan.passes) {
    for (std::uint32_t y = pass.tile.origin.y; y < pass.tile.origin.y + pass.tile.size.y; ++y) {
      for (std::uint32_t x = pass.tile.origin.x; x < pass.tile.origin.x + pass.tile.size.x; ++x) {
        ASSERT_LT(x, extent.x);
        ASSERT_LT(y, extent.y);
        log[std::size_t(y) * extent.x + x].push_back(pass.sampleIndex);
      }
    }
  }
}

// Every pixel got samples 0, 1, ..., n-1 in this order: what `raylab render --spp n` adds.
void expectRenderOrder(const SampleLog& log, std::uint32_t n) {
  for (std::size_t i = 0; i < log.size(); ++i) {
    ASSERT_EQ(log[i].size(), n) << "pixel " << i;
    for (std::uint32_t k = 0; k < n; ++k) ASSERT_EQ(log[i][k], k) << "pixel " << i;
  }
}

Scheduler makeScheduler(glm::uvec2 full, double secondsPerPixelSample) {
  Scheduler scheduler;
  setFullExtent(scheduler, full);
  scheduler.cost.secondsPerPixelSample = secondsPerPixelSample;
  scheduler.cost.traceMeasurements = secondsPerPixelSample > 0.0 ? 1 : 0;
  return scheduler;
}

TEST(SchedulerTest, TilesCoverTheImageOnceOnWorkgroupBoundaries) {
  const glm::uvec2 extent(203, 77);
  std::vector<int> covered(std::size_t(extent.x) * extent.y, 0);
  for (const Tile& tile : makeTiles(extent, {64, 32})) {
    EXPECT_EQ(tile.origin.x % 8, 0u);
    EXPECT_EQ(tile.origin.y % 8, 0u);
    for (std::uint32_t y = tile.origin.y; y < tile.origin.y + tile.size.y; ++y) {
      for (std::uint32_t x = tile.origin.x; x < tile.origin.x + tile.size.x; ++x) ++covered[y * extent.x + x];
    }
  }
  for (int count : covered) ASSERT_EQ(count, 1);
}

TEST(SchedulerTest, FullPassFramesAddOneSampleOfEveryPixelInRenderOrder) {
  Scheduler scheduler = makeScheduler({100, 60}, 1e-6);
  SampleLog log;
  for (int frame = 0; frame < 5; ++frame) {
    const FramePlan plan = planFrame(scheduler, 0.01 * frame, frame == 0, FrameKind::kFullPass);
    EXPECT_EQ(plan.reset, frame == 0);
    EXPECT_FALSE(plan.preview);
    EXPECT_EQ(plan.traceExtent, glm::uvec2(100, 60));
    logPlan(plan, plan.traceExtent, log);
  }
  expectRenderOrder(log, 5);
  EXPECT_EQ(scheduler.sampleIndex, 5u);
}

TEST(SchedulerTest, StillFramesStayWithinTheBudgetAndStillAddSamplesInRenderOrder) {
  const double perPixelSample = 2e-7;
  Scheduler scheduler = makeScheduler({300, 200}, perPixelSample);
  scheduler.settings.targetFrameSeconds = 0.05;
  scheduler.cost.overheadSeconds = 0.01;
  SampleLog log;
  double now = 10.0;  // long after any change: still
  std::uint64_t total = 0;
  while (scheduler.sampleIndex < 3) {
    const FramePlan plan = planFrame(scheduler, now, false, FrameKind::kInteractive);
    ASSERT_FALSE(plan.preview);
    ASSERT_FALSE(plan.passes.empty());
    EXPECT_LE(double(plan.pixelSamples) * perPixelSample, 0.04 + 1e-9) << "over the trace budget";
    logPlan(plan, plan.traceExtent, log);
    total += plan.pixelSamples;
    now += 0.05;
  }
  // Finish the pass in progress, then check the order of everything traced.
  while (scheduler.nextTile != 0) logPlan(planFrame(scheduler, now, false, FrameKind::kInteractive), {300, 200}, log);
  expectRenderOrder(log, scheduler.sampleIndex);
  EXPECT_GE(total, 3u * 300 * 200);
}

TEST(SchedulerTest, RefinementBandsHoldAboutTheSamePixelsAtAnyWidth) {
  EXPECT_EQ(bandRows(640, 640 * 32), 32u);
  EXPECT_EQ(bandRows(1280, 640 * 32), 16u);
  EXPECT_EQ(bandRows(4000, 640 * 32), 8u);  // at least one workgroup row
  EXPECT_EQ(bandRows(100, 640 * 32), 200u);
}

// Bands differ tenfold in cost (sky against glass): once each band's cost is measured, a frame takes bands while
// their measured costs fit the budget, where the mean cost per pixel-sample would overrun or idle.
TEST(SchedulerTest, RefinementPacksFramesByEachBandsMeasuredCost) {
  Scheduler scheduler = makeScheduler({640, 256}, 1e-6);
  scheduler.settings.targetFrameSeconds = 0.05;
  scheduler.cost.overheadSeconds = 0.01;  // budget 40 ms
  double now = 10.0;
  SampleLog log;
  // The first pass is planned by the mean cost; every band it traced is then measured.
  std::vector<double> bandSeconds;
  while (scheduler.sampleIndex == 0) {
    const FramePlan plan = planFrame(scheduler, now, false, FrameKind::kInteractive);
    logPlan(plan, plan.traceExtent, log);
    for (const TracePass& pass : plan.passes) {
      const double seconds = pass.tileIndex % 3 == 0 ? 0.030 : 0.004;  // every third band is costly
      addTileMeasurement(scheduler, plan.tiling, pass.tileIndex, seconds);
      bandSeconds.push_back(seconds);
    }
    now += 0.05;
  }
  ASSERT_EQ(scheduler.tiles.size(), 8u);  // 640x32 bands
  for (int frame = 0; frame < 6; ++frame) {
    const FramePlan plan = planFrame(scheduler, now, false, FrameKind::kInteractive);
    logPlan(plan, plan.traceExtent, log);
    double planned = 0.0;
    for (const TracePass& pass : plan.passes) planned += scheduler.tileSeconds[pass.tileIndex];
    EXPECT_LE(planned, 0.040 + 1e-9) << "frame " << frame;
    // The next band would not have fitted.
    EXPECT_GT(planned + scheduler.tileSeconds[scheduler.nextTile], 0.040) << "frame " << frame;
    now += 0.05;
  }
  while (scheduler.nextTile != 0) logPlan(planFrame(scheduler, now, false, FrameKind::kInteractive), {640, 256}, log);
  expectRenderOrder(log, scheduler.sampleIndex);
}

TEST(SchedulerTest, AMeasurementOfAnOlderTilingIsIgnored) {
  Scheduler scheduler = makeScheduler({640, 256}, 1e-6);
  const FramePlan first = planFrame(scheduler, 10.0, true, FrameKind::kInteractive);
  setFullExtent(scheduler, {320, 256});
  const FramePlan second = planFrame(scheduler, 20.0, false, FrameKind::kInteractive);
  ASSERT_NE(first.tiling, second.tiling);
  addTileMeasurement(scheduler, first.tiling, 0, 1.0);
  EXPECT_EQ(scheduler.tileSeconds[0], 0.0);
  addTileMeasurement(scheduler, second.tiling, 0, 0.01);
  EXPECT_EQ(scheduler.tileSeconds[0], 0.01);
}

// Frames that are not displayed have no display pass, blit, UI or presentation: they trace for the whole target.
TEST(SchedulerTest, UnshownFramesRefineOnlyWhenStillAndUseTheWholeTarget) {
  const double perPixelSample = 1e-7;
  Scheduler scheduler = makeScheduler({640, 512}, perPixelSample);
  scheduler.settings.targetFrameSeconds = 0.05;
  scheduler.cost.overheadSeconds = 0.02;
  planFrame(scheduler, 1.0, true, FrameKind::kInteractive);  // the camera moved: a preview
  EXPECT_FALSE(refiningQuietly(scheduler, 1.0));
  EXPECT_FALSE(refiningQuietly(scheduler, 1.0 + scheduler.settings.settleSeconds));  // still the preview
  const double still = 1.0 + scheduler.settings.settleSeconds + 0.01;
  const FramePlan shown = planFrame(scheduler, still, false, FrameKind::kInteractive);
  EXPECT_FALSE(shown.preview);
  EXPECT_TRUE(refiningQuietly(scheduler, still));
  const FramePlan unshown = planFrame(scheduler, still + 0.05, false, FrameKind::kUnshown);
  EXPECT_NEAR(double(shown.pixelSamples) * perPixelSample, 0.030, 0.0035);    // target - overhead, to a band
  EXPECT_NEAR(double(unshown.pixelSamples) * perPixelSample, 0.050, 0.0035);  // the whole target
  scheduler.settings.sppLimit = scheduler.sampleIndex;
  EXPECT_FALSE(refiningQuietly(scheduler, still + 0.1)) << "nothing left to trace";
}

TEST(SchedulerTest, MovingTracesAReducedResolutionSizedToTheBudgetThenRefines) {
  Scheduler scheduler = makeScheduler({1280, 720}, 4e-7);
  scheduler.settings.targetFrameSeconds = 0.05;
  scheduler.cost.overheadSeconds = 0.01;
  const FramePlan moving = planFrame(scheduler, 1.0, true, FrameKind::kInteractive);
  EXPECT_TRUE(moving.reset);
  EXPECT_TRUE(moving.preview);
  // 40 ms at 0.4 us per pixel-sample: 100k pixels, about 421x237 at 16:9.
  EXPECT_NEAR(double(moving.traceExtent.x) * moving.traceExtent.y, 0.04 / 4e-7, 0.03 * 0.04 / 4e-7);
  EXPECT_NEAR(double(moving.traceExtent.x) / moving.traceExtent.y, 1280.0 / 720.0, 0.02);
  EXPECT_EQ(moving.pixelSamples, std::uint64_t(moving.traceExtent.x) * moving.traceExtent.y) << "one whole pass";

  // A slower scene gets a smaller preview.
  const glm::uvec2 slower = previewExtent({1280, 720}, 0.04, 16e-7, 1.0f / 16.0f);
  EXPECT_NEAR(double(slower.x), moving.traceExtent.x / 2.0, 2.0);

  // Still within the settle time: the preview keeps accumulating.
  const FramePlan settling = planFrame(scheduler, 1.1, false, FrameKind::kInteractive);
  EXPECT_TRUE(settling.preview);
  EXPECT_FALSE(settling.reset);
  EXPECT_EQ(settling.passes.front().sampleIndex, 1u);

  // Settled: full resolution from sample 0.
  const FramePlan still = planFrame(scheduler, 1.0 + scheduler.settings.settleSeconds + 0.01, false,
                                    FrameKind::kInteractive);
  EXPECT_TRUE(still.reset);
  EXPECT_FALSE(still.preview);
  EXPECT_EQ(still.traceExtent, glm::uvec2(1280, 720));
  EXPECT_EQ(still.passes.front().sampleIndex, 0u);
}

TEST(SchedulerTest, AResizeWhileMovingNeverKeepsAPreviewLargerThanTheNewImage) {
  // A budget of about 620x349 pixels at 1280x720; then the window becomes 640x200, where the whole image fits
  // the budget and is barely wider than the old preview (the preview's size hysteresis must not keep it).
  Scheduler scheduler = makeScheduler({1280, 720}, 0.05 / (620.0 * 349.0));
  scheduler.settings.targetFrameSeconds = 0.05;
  const FramePlan before = planFrame(scheduler, 1.0, true, FrameKind::kInteractive);
  EXPECT_NEAR(double(before.traceExtent.x), 620.0, 2.0);
  setFullExtent(scheduler, {640, 200});
  const FramePlan plan = planFrame(scheduler, 1.01, true, FrameKind::kInteractive);
  EXPECT_TRUE(plan.reset);
  EXPECT_EQ(plan.traceExtent, glm::uvec2(640, 200));
}

TEST(SchedulerTest, StopsAtTheSppLimit) {
  Scheduler scheduler = makeScheduler({64, 64}, 1e-7);
  scheduler.settings.sppLimit = 2;
  for (int frame = 0; frame < 4; ++frame) planFrame(scheduler, frame, frame == 0, FrameKind::kFullPass);
  EXPECT_EQ(scheduler.sampleIndex, 2u);
  EXPECT_TRUE(converged(scheduler));
  EXPECT_TRUE(planFrame(scheduler, 10.0, false, FrameKind::kInteractive).passes.empty());
  planFrame(scheduler, 11.0, true, FrameKind::kFullPass);
  EXPECT_FALSE(converged(scheduler)) << "a change starts over";
}

TEST(SchedulerTest, AKernelCompilationMovesTheCostEstimateAtMostFourfold) {
  CostModel cost;
  addTraceMeasurement(cost, 1000, 1e-3);
  EXPECT_DOUBLE_EQ(cost.secondsPerPixelSample, 1e-6);
  addTraceMeasurement(cost, 1000, 2.0);  // the driver compiled for two seconds
  EXPECT_LE(cost.secondsPerPixelSample, 4e-6 * 1.0000001);
}

TEST(ScriptTest, ParsesEveryActionSortedByFrame) {
  const std::vector<ScriptEvent> events = parseScript(
      "# comment\n"
      "at 5 orbit 10 -5\n"
      "\n"
      "at 2 set material \"red plastic\" rho_d 0.1 0.6 0.1  # trailing comment\n"
      "at 2 set light key intensity 1 2 3\n"
      "at 3 model ground phong\n"
      "at 4 resize 320 200\n"
      "at 6 screenshot out/a.exr\n"
      "at 1 zoom 0.5\n"
      "at 1 pan 0.1 0\n"
      "at 7 set exposure -1.5\n"
      "at 7 set max-depth 3\n"
      "at 8 set integrator path\n"
      "at 8 set environment strength 2.5\n"
      "at 8 set environment rotation -45\n",
      "s.txt");
  ASSERT_EQ(events.size(), 13u);
  EXPECT_EQ(events[0].action, ScriptAction::kZoom);
  EXPECT_EQ(events[1].action, ScriptAction::kPan);
  EXPECT_EQ(events[2].action, ScriptAction::kSetMaterial);
  EXPECT_EQ(events[2].name, "red plastic");
  EXPECT_EQ(events[2].param, "rho_d");
  EXPECT_EQ(events[2].value, glm::vec3(0.1f, 0.6f, 0.1f));
  EXPECT_EQ(events[2].where, "s.txt:4");
  EXPECT_EQ(events[3].action, ScriptAction::kSetLightIntensity);
  EXPECT_EQ(events[4].action, ScriptAction::kModel);
  EXPECT_EQ(events[4].param, "phong");
  EXPECT_EQ(events[5].action, ScriptAction::kResize);
  EXPECT_EQ(events[5].value.x, 320.0f);
  EXPECT_EQ(events[6].action, ScriptAction::kOrbit);
  EXPECT_EQ(events[7].action, ScriptAction::kScreenshot);
  EXPECT_FALSE(resetsAccumulation(events[7]));
  EXPECT_EQ(events[8].action, ScriptAction::kSetExposure);
  EXPECT_FALSE(resetsAccumulation(events[8]));
  EXPECT_EQ(events[9].action, ScriptAction::kSetMaxDepth);
  EXPECT_TRUE(resetsAccumulation(events[9]));
  EXPECT_EQ(events[10].action, ScriptAction::kSetIntegrator);
  EXPECT_EQ(events[10].param, "path");
  EXPECT_EQ(events[11].action, ScriptAction::kSetEnvironmentStrength);
  EXPECT_EQ(events[11].value.x, 2.5f);
  EXPECT_EQ(events[12].action, ScriptAction::kSetEnvironmentRotation);
  EXPECT_EQ(events[12].value.x, -45.0f);
  EXPECT_TRUE(resetsAccumulation(events[12]));
}

TEST(ScriptTest, ErrorsNameTheFileAndLine) {
  const std::map<std::string, std::string> cases = {
      {"at x orbit 1 2", "frame"},
      {"at 1 spin 3", "unknown action 'spin'"},
      {"at 1 orbit 1", "orbit"},
      {"at 1 zoom abc", "number"},
      {"at 1 zoom 0", "[0.001, 1000]"},
      {"at 1 zoom 1e30", "[0.001, 1000]"},
      {"at 1 pan 1e30 0", "1000 view heights"},
      {"at 1 resize 4 4", "8..16384"},
      {"at 1 set light key colour 1 1 1", "'colour'"},
      {"at 1 set material \"unterminated rho_d 1", "unterminated"},
      {"at 1 screenshot a.tif", ".exr or .png"},
      {"at 0 screenshot a.exr", "frame 0 would be black"},
      {"at 1 set light key cone 30 20", "inner < outer"},
      {"at 1 set light key direction 0 0 0", "non-zero"},
      {"at 1 set light key intensity 1e39 1 1", "number"},
      {"orbit 1 2", "at <frame>"},
      {"at 1 set integrator bidir", "slides or path"},
      {"at 1 set environment strength -1", ">= 0"},
      {"at 1 set environment exposure 1", "strength and rotation"},
      {"at 1 set environment rotation nan", "number"},
      {"at 1 set exposure 1e30", "within [-20, 20]"},
      {"at 1 set exposure -21", "within [-20, 20]"},
      {"at 1 pick 4294967295 2", "outside any window"},
      {"at 1 pick 4294967296 2", "whole number"},
  };
  for (const auto& [line, mentions] : cases) {
    try {
      parseScript("# first line\n" + line + "\n", "script.txt");
      ADD_FAILURE() << "accepted: " << line;
    } catch (const Error& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("script.txt:2"), std::string::npos) << message;
      EXPECT_NE(message.find(mentions), std::string::npos) << message;
    }
  }
}

// A user can aim a spot or directional light and open a spot's cone from a script, and is told when the
// light has no such property.
TEST(ScriptTest, LightDirectionAndConeChangeSpotAndDirectionalLights) {
  Scene scene;
  PunctualLight spot{};
  spot.type = gpu::kLightSpot;
  spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  PunctualLight point{};
  point.type = gpu::kLightPoint;
  scene.lights = {{"spot", spot}, {"bulb", point}};
  const std::vector<ScriptEvent> events = parseScript(
      "at 1 set light spot direction 0 0 -2\n"
      "at 1 set light spot cone 10 30\n",
      "s.txt");
  for (const ScriptEvent& event : events) EXPECT_TRUE(applyToScene(event, scene).lights);
  EXPECT_EQ(scene.lights[0].record.direction, glm::vec3(0.0f, 0.0f, -1.0f));  // normalised
  EXPECT_NEAR(scene.lights[0].record.cosInner, std::cos(glm::radians(10.0f)), 1e-6f);
  EXPECT_NEAR(scene.lights[0].record.cosOuter, std::cos(glm::radians(30.0f)), 1e-6f);

  const std::vector<ScriptEvent> wrong = parseScript("at 1 set light bulb cone 10 30\n", "s.txt");
  try {
    applyToScene(wrong[0], scene);
    ADD_FAILURE() << "a point light accepted a cone";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("s.txt:1: light 'bulb' is not a spot light"), std::string::npos)
        << error.what();
  }
  const std::vector<ScriptEvent> unknown = parseScript("at 1 set light lamp intensity 1 1 1\n", "s.txt");
  try {
    applyToScene(unknown[0], scene);
    ADD_FAILURE() << "an unknown light was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("(lights: 'spot', 'bulb')"), std::string::npos) << error.what();
  }
}

TEST(ScriptTest, CheckFollowsModelSwitchesAndNamesTheLine) {
  Scene scene;
  scene.materials = {{"ball", lambertMaterial(glm::vec3(0.5f))}};
  scene.lights = {{"key", pointLight(glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(10.0f))}};
  // s exists only after the switch to phong.
  EXPECT_NO_THROW(checkScript(parseScript("at 1 model ball phong\nat 2 set material ball s 20\n", "a"), scene));
  const auto expectError = [&](const std::string& text, const std::string& mentions) {
    try {
      checkScript(parseScript(text, "b"), scene);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(mentions), std::string::npos) << error.what();
    }
  };
  expectError("at 2 set material ball s 20\n", "b:1");
  expectError("at 1 set material ball rho_d 2\n", "outside");
  expectError("at 1 model ball velvet\n", "unknown model 'velvet'");
  expectError("at 1 set light sun intensity 1 1 1\n", "no light 'sun'");
  expectError("at 1\nat 2 set material plate rho_d 0.5\n", "b:1");
  // Named metals, as --material ball=ggx_conductor:metal=Au and extras' "metal": "Au" take them.
  Scene metal = scene;
  const std::vector<ScriptEvent> events = parseScript("at 1 model ball ggx_conductor\nat 2 set material ball metal Au\n", "c");
  checkScript(events, metal);
  for (const ScriptEvent& event : events) applyToScene(event, metal);
  gpu::MaterialRecord gold = defaultRecord(modelId("ggx_conductor"));
  applyPreset(gold, "metal", "Au", "test");
  EXPECT_EQ(getParam(metal.materials[0].record, "eta"), getParam(gold, "eta"));
  EXPECT_EQ(getParam(metal.materials[0].record, "k"), getParam(gold, "k"));
  expectError("at 1 model ball ggx_conductor\nat 2 set material ball metal Unobtainium\n", "Unobtainium");
  // openpbr's layers: an out-of-range weight, a negative volume depth, NaN, each naming the line and parameter.
  expectError("at 1 model ball openpbr\nat 2 set material ball coat_weight 1.5\n", "coat_weight = 1.5 is outside [0, 1]");
  expectError("at 1 model ball openpbr\nat 2 set material ball transmission_depth -1\n", "transmission_depth = -1");
  expectError("at 1 model ball openpbr\nat 2 set material ball fuzz_weight nan\n", "b:2");
  expectError("at 1 model ball openpbr\nat 2 set material ball geometry_opacity 2\n", "geometry_opacity");
  // transmission_depth 0 is the specification's "no volume", not an error.
  EXPECT_NO_THROW(checkScript(parseScript("at 1 model ball openpbr\nat 2 set material ball transmission_depth 0\n", "d"),
                              scene));
}

// One bound on what emits light, checked before the window opens: a strength that would make strength x the
// brightest texel overflow (3e38 used to be accepted and render NaN), a light's intensity likewise; and an
// environment edit without an environment.
TEST(ScriptTest, EditsThatWouldOverflowTheImageAreRefusedNamingTheLine) {
  Scene scene;
  scene.materials = {{"ball", lambertMaterial(glm::vec3(0.5f))}};
  scene.lights = {{"key", pointLight(glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(10.0f))}};
  const auto errorOf = [&](const Scene& s, const std::string& text) -> std::string {
    try {
      checkScript(parseScript(text, "s"), s);
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_NE(errorOf(scene, "at 1 set environment strength 2\n").find("s:1: the scene has no environment image"),
            std::string::npos);
  scene.environment.width = 2;
  scene.environment.height = 1;
  scene.environment.texels = {glm::vec3(1000.0f), glm::vec3(1.0f)};
  scene.environment.brightest = 1000.0f;
  EXPECT_EQ(errorOf(scene, "at 1 set environment strength 1e17\n"), "");
  EXPECT_NE(errorOf(scene, "at 1 set environment strength 1e18\n").find("s:1: environment strength 1e+18 x"),
            std::string::npos);
  EXPECT_NE(errorOf(scene, "at 1 set environment strength 3e38\n").find("over raylab's limit"), std::string::npos);
  try {
    parseScript("at 1 set light key intensity 3e38 0 0\n", "s");
    ADD_FAILURE() << "an intensity of 3e38 was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("s:1"), std::string::npos) << error.what();
  }
}

TEST(CameraTest, OrbitKeepsTheTargetAndDistanceAndNeverReachesThePoles) {
  Camera camera;
  camera.position = {0.0f, 1.0f, 5.0f};
  camera.target = {0.0f, 0.5f, 0.0f};
  const float distance = glm::length(camera.position - camera.target);
  for (int i = 0; i < 200; ++i) {
    orbitCamera(camera, 0.05f, 0.1f);  // far more pitch than up to the pole
    ASSERT_NEAR(glm::length(camera.position - camera.target), distance, 1e-3f * distance);
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    ASSERT_LT(std::abs(glm::dot(forward, camera.up)), std::cos(glm::radians(1.0f))) << "at step " << i;
  }
  EXPECT_GT(camera.position.y, camera.target.y) << "positive pitch raises the camera";
  for (int i = 0; i < 200; ++i) orbitCamera(camera, 0.0f, -0.1f);
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  EXPECT_LT(std::abs(glm::dot(forward, camera.up)), std::cos(glm::radians(1.0f)));
  EXPECT_LT(camera.position.y, camera.target.y);
}

TEST(CameraTest, PanZoomLookAndFly) {
  Camera camera;
  camera.position = {0.0f, 0.0f, 4.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  panCamera(camera, 0.5f, 0.0f);
  EXPECT_GT(camera.target.x, 0.0f);
  EXPECT_FLOAT_EQ(camera.position.x, camera.target.x) << "pan moves both together";
  zoomCamera(camera, 0.5f, 1e-3f);
  EXPECT_NEAR(glm::length(camera.position - camera.target), 2.0f, 1e-5f);
  zoomCamera(camera, 1e-9f, 0.1f);
  EXPECT_NEAR(glm::length(camera.position - camera.target), 0.1f, 1e-5f) << "never closer than the minimum";
  const glm::vec3 position = camera.position;
  lookCamera(camera, 0.3f, 0.2f);
  EXPECT_EQ(camera.position, position) << "looking turns the view, not the camera";
  EXPECT_GT(camera.target.y, camera.position.y) << "positive pitch looks up";
  flyCamera(camera, {0.0f, 0.0f, 1.0f});
  EXPECT_NEAR(glm::length(camera.position - position), 1.0f, 1e-5f);
}

// Where `point` lands in the image of `camera` (aspect 16:9): normalised device coordinates, and whether it is
// in front of the camera.
std::pair<glm::vec2, bool> project(const Camera& camera, glm::vec3 point) {
  const glm::vec3 w = glm::normalize(camera.target - camera.position);
  const glm::vec3 u = glm::normalize(glm::cross(w, camera.up));
  const glm::vec3 v = glm::cross(u, w);
  const glm::vec3 d = point - camera.position;
  const float depth = glm::dot(d, w);
  const float tanHalf = std::tan(0.5f * camera.yfov);
  return {glm::vec2(glm::dot(d, u) / (depth * tanHalf * 16.0f / 9.0f), glm::dot(d, v) / (depth * tanHalf)),
          depth > 0.0f};
}

glm::vec3 boundsCentre(const Scene& scene) {
  glm::vec3 low(1e30f), high(-1e30f);
  for (const MeshInstance& instance : scene.instances) {
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
      const glm::vec3 world(instance.transform * glm::vec4(p, 1.0f));
      low = glm::min(low, world);
      high = glm::max(high, world);
    }
  }
  for (const Sphere& sphere : scene.spheres) {
    low = glm::min(low, sphere.center - sphere.radius);
    high = glm::max(high, sphere.center + sphere.radius);
  }
  return 0.5f * (low + high);
}

// Issue 9: the orbit pivot was 1 unit in front of the glTF camera, so a 20 degree orbit slid every committed
// scene out of frame and 90 degrees showed empty sky. It is now where the view ray meets the scene.
TEST(CameraTest, OrbitingEveryCommittedSceneKeepsItsCentreInFrame) {
  WarningCapture quiet;
  for (const std::filesystem::path& file : assetFiles()) {
    const Scene scene = loadGltfFile(file.string(), {});
    const glm::vec3 centre = boundsCentre(scene);
    for (float yaw : {90.0f, 180.0f, -90.0f}) {
      Camera camera = scene.camera;
      orbitCamera(camera, glm::radians(yaw), 0.0f);
      const auto [ndc, inFront] = project(camera, centre);
      EXPECT_TRUE(inFront && std::abs(ndc.x) < 1.0f && std::abs(ndc.y) < 1.0f)
          << file.filename() << " orbited " << yaw << " degrees: the scene's centre is at (" << ndc.x << ", "
          << ndc.y << ")" << (inFront ? "" : " behind the camera");
      // Orbiting by yaw turns about the vertical: the camera keeps its height (it used to end under the floor).
      EXPECT_NEAR(camera.position.y, scene.camera.position.y, 1e-3f * glm::length(scene.camera.position - centre))
          << file.filename() << " orbited " << yaw << " degrees";
    }
    // The wheel zooms in proportion to the distance to the scene: ten steps in get much closer than 1 unit.
    Camera camera = scene.camera;
    const float before = glm::length(camera.target - camera.position);
    for (int i = 0; i < 10; ++i) zoomCamera(camera, 0.9f, 1e-4f);
    EXPECT_NEAR(glm::length(camera.target - camera.position), before * std::pow(0.9f, 10.0f), 1e-3f * before)
        << file.filename();
  }
}

}  // namespace
}  // namespace raylab::test
