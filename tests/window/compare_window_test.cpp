// The viewer as a comparison instrument, under Xvfb on the real device: the split view's two sides are the renders
// of the scene and of the scene with the material switched (`raylab render --material`), the window shows each on
// its side of the divider, the difference view of identical sides is exactly zero and of two models the
// difference of the two renders, picking names the material under a pixel with its radiance and sample count,
// and the lobe plot holds the values `raylab brdf eval` computes on the device. Bad --compare text exits 2
// before any window opens.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "builtin_scenes/load_scene.h"
#include "window/window_support.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

// Image size of these tests, and the rows below the sides' labels (the overlay draws them at the top).
constexpr std::uint32_t kWidth = 256, kHeight = 256;
constexpr std::uint32_t kFirstUnlabelledRow = 96;
const std::string kWard = "red plastic=ward:rho_d=0.2/0.5/0.2,rho_s=0.3,alpha_x=0.3,alpha_y=0.1";
// The scene's own Cook-Torrance material, written out: the right side is then the left side.
const std::string kSame = "red plastic=cooktorrance:rho_d=0.6/0.1/0.1,rho_s=1,m=0.2,eta=1.5";

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
  std::array<int, 3> at(int x, int y) const {
    const unsigned char* p = &pixels[(std::size_t(y) * width + x) * 3];
    return {p[0], p[1], p[2]};
  }
};

Rgb8 readPng(const std::string& path) {
  Rgb8 image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  EXPECT_NE(data, nullptr) << path;
  if (data != nullptr) {
    image.pixels.assign(data, data + std::size_t(image.width) * image.height * 3);
    stbi_image_free(data);
  }
  return image;
}

// Mean absolute difference per channel of `a` and `b` over columns [x0, x1) of rows [y0, height).
double meanDifference(const Rgb8& a, const Rgb8& b, int x0, int x1, int y0 = int(kFirstUnlabelledRow)) {
  double sum = 0.0;
  std::size_t count = 0;
  for (int y = y0; y < a.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      for (int c = 0; c < 3; ++c) sum += std::abs(a.at(x, y)[c] - b.at(x, y)[c]);
      count += 3;
    }
  }
  return sum / double(count);
}

std::vector<std::string> viewArguments(const std::string& compare, const std::string& shot,
                                       const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = {kMinimalScene, "--width", std::to_string(kWidth), "--height",
                                        std::to_string(kHeight), "--seed", "5", "--no-panel", "--compare", compare,
                                        "--screenshot", shot + ".exr", "--capture-window", shot + "_window.png"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  return arguments;
}

std::vector<std::string> renderArguments(const std::string& spp) {
  return {kMinimalScene, "--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--seed", "5",
          "--spp", spp};
}

// The display pass's false colour (shaders/display.comp) of `t` in [0, 1], as 8-bit sRGB.
std::array<int, 3> falseColour(float t) {
  const float stops[5][3] = {{0.05f, 0.03f, 0.20f}, {0.10f, 0.30f, 0.85f}, {0.10f, 0.75f, 0.35f},
                             {0.95f, 0.85f, 0.10f}, {1.00f, 1.00f, 1.00f}};
  const float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(int(x), 3);
  std::array<int, 3> colour{};
  for (int c = 0; c < 3; ++c) {
    colour[c] = int(std::lround(255.0f * (stops[i][c] + (stops[i + 1][c] - stops[i][c]) * (x - float(i)))));
  }
  return colour;
}

TEST(CompareWindowTest, SplitViewSidesEqualTheRendersOfTheSceneAndOfTheSwitchedMaterial) {
  const std::string dir = scratchDir();
  const std::string shot = dir + "/split";
  expectCleanRun(runView(viewArguments(kWard, shot, {"--frames", "4"})));
  const Image left = readExr(shot + ".exr");
  const Image right = readExr(shot + "_compare.exr");
  const Image sceneRender = renderReference(renderArguments("4"), dir + "/split_scene.exr");
  std::vector<std::string> switched = renderArguments("4");
  switched.insert(switched.end(), {"--material", kWard});
  const Image switchedRender = renderReference(switched, dir + "/split_switched.exr");
  expectSameImage(left, sceneRender, "the left side against raylab render");
  expectSameImage(right, switchedRender, "the right side against raylab render --material");

  // The window: left of the divider (the middle column) the scene's image, right of it the switched one, each
  // equal to its render's PNG up to the display pass's rounding; the two sides differ on the ball.
  const Rgb8 window = readPng(shot + "_window.png");
  ASSERT_EQ(window.width, int(kWidth));
  ASSERT_EQ(window.height, int(kHeight));
  const Rgb8 scenePng = readPng(dir + "/split_scene.exr.png");
  const Rgb8 switchedPng = readPng(dir + "/split_switched.exr.png");
  const int divider = int(kWidth / 2);
  EXPECT_LT(meanDifference(window, scenePng, 0, divider - 3), 0.5) << "left of the divider is not the scene";
  EXPECT_LT(meanDifference(window, switchedPng, divider + 3, int(kWidth)), 0.5)
      << "right of the divider is not the switched material";
  EXPECT_GT(meanDifference(window, scenePng, divider + 3, int(kWidth)), 0.5)
      << "right of the divider shows the scene, not the switched material";
  EXPECT_GT(meanDifference(scenePng, switchedPng, divider + 3, int(kWidth), 0), 3.0)
      << "the two models look alike: the test would not see a wrong side";

  // The screenshot's PNG is as displayed: the split view, each side its render's PNG (it used to be side A only).
  const Rgb8 screenshot = readPng(shot + ".png");
  EXPECT_LT(meanDifference(screenshot, scenePng, 0, divider, 0), 0.01) << "the screenshot's left side";
  EXPECT_LT(meanDifference(screenshot, switchedPng, divider, int(kWidth), 0), 0.01) << "the screenshot's right side";
}

TEST(CompareWindowTest, DifferenceOfIdenticalSidesIsExactlyZeroInTheImageAndTheWindow) {
  const std::string dir = scratchDir();
  const std::string shot = dir + "/same";
  const std::string script = writeScript("same.txt", "at 1 set difference absolute 0.05\n");
  expectCleanRun(runView(viewArguments(kSame, shot, {"--frames", "3", "--script", script})));
  const Image difference = readExr(shot + "_difference.exr");
  ASSERT_EQ(difference.width, kWidth);
  for (std::size_t i = 0; i < difference.rgba.size(); ++i) {
    if (i % 4 != 3) {
      ASSERT_EQ(difference.rgba[i], 0.0f) << "float " << i;
    }
  }
  EXPECT_EQ(readExr(shot + ".exr").rgba, readExr(shot + "_compare.exr").rgba);
  const Rgb8 window = readPng(shot + "_window.png");
  const std::array<int, 3> zero = falseColour(0.0f);
  // The screenshot's PNG is the difference view as displayed: the ramp's 0 everywhere.
  const Rgb8 screenshot = readPng(shot + ".png");
  for (std::size_t i = 0; i < screenshot.pixels.size(); ++i) ASSERT_EQ(int(screenshot.pixels[i]), zero[i % 3]) << "byte " << i;
  for (int y = int(kFirstUnlabelledRow); y < window.height - 40; ++y) {  // above the colour bar
    for (int x = 0; x < window.width; ++x) ASSERT_EQ(window.at(x, y), zero) << "pixel " << x << ", " << y;
  }
}

// The panel's mean and largest |A - B| are measured from a frame's own copy of both sides when that frame completes
// (no stall of the frames in flight): they are those of the two renders at the samples the frame had.
TEST(CompareWindowTest, DifferenceStatisticsAreThoseOfTheTwoRenders) {
  const std::string dir = scratchDir();
  std::vector<std::string> arguments = viewArguments(kWard, dir + "/stats", {"--frames", "3"});
  arguments.erase(std::find(arguments.begin(), arguments.end(), "--no-panel"));  // the statistics are the panel's
  const CommandResult result = runView(arguments);
  expectCleanRun(result);
  const std::string prefix = "raylab view: difference absolute mean ";
  const std::size_t at = result.output.rfind(prefix);  // the last measurement
  ASSERT_NE(at, std::string::npos) << "no statistics were measured:\n" << result.output;
  double mean = 0.0, largest = 0.0;
  unsigned spp = 0;
  ASSERT_EQ(std::sscanf(result.output.c_str() + at + prefix.size(), "%lf max %lf (%u spp)", &mean, &largest, &spp), 3)
      << result.output.substr(at);
  // A frame reuses the slot of the frame two before, so the third frame measures again: at 3 spp, where a
  // statistic that forgot to divide the sums by the sample count would be three times too large.
  ASSERT_GE(spp, 2u) << result.output;
  const Image a = renderReference(renderArguments(std::to_string(spp)), dir + "/stats_scene.exr");
  std::vector<std::string> switched = renderArguments(std::to_string(spp));
  switched.insert(switched.end(), {"--material", kWard});
  const Image b = renderReference(switched, dir + "/stats_switched.exr");
  double expectedSum = 0.0, expectedLargest = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(a.rgba[i + c]) - double(b.rgba[i + c])));
    expectedSum += d;
    expectedLargest = std::max(expectedLargest, d);
  }
  const double expectedMean = expectedSum / double(a.width * a.height);
  EXPECT_GT(expectedMean, 0.01) << "the models hardly differ: the test would not see wrong statistics";
  // The viewer divides the sums by the sample count where raylab render multiplies by its reciprocal: rounding.
  EXPECT_NEAR(mean, expectedMean, 1e-5 * expectedMean);
  EXPECT_NEAR(largest, expectedLargest, 1e-5 * expectedLargest);
}

TEST(CompareWindowTest, DifferenceOfTwoModelsIsTheDifferenceOfTheirRenders) {
  const std::string dir = scratchDir();
  const std::string shot = dir + "/models";
  const float scale = 0.2f;
  const std::string script = writeScript("models.txt", "at 1 set difference absolute 0.2\n");
  expectCleanRun(runView(viewArguments(kWard, shot, {"--frames", "3", "--script", script})));
  const Image a = renderReference(renderArguments("3"), dir + "/models_scene.exr");
  std::vector<std::string> switched = renderArguments("3");
  switched.insert(switched.end(), {"--material", kWard});
  const Image b = renderReference(switched, dir + "/models_switched.exr");
  const Image difference = readExr(shot + "_difference.exr");
  ASSERT_EQ(difference.width, a.width);
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double expected = std::abs(double(a.rgba[i]) - double(b.rgba[i]));
    largest = std::max(largest, expected);
    worst = std::max(worst, std::abs(difference.rgba[i] - expected) / (1e-5 * (std::abs(a.rgba[i]) + std::abs(b.rgba[i])) + 1e-7));
  }
  EXPECT_LT(worst, 1.0) << "the difference image is not |A - B| of the two renders";
  EXPECT_GT(largest, 0.05) << "the models hardly differ: the test would not see a wrong difference";

  // The window shows the largest channel of |A - B| over the scale in false colour.
  const Rgb8 window = readPng(shot + "_window.png");
  std::size_t off = 0, count = 0;
  for (std::uint32_t y = kFirstUnlabelledRow; y < kHeight - 40; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec4 d = glm::abs(a.at(x, y) - b.at(x, y));
      const std::array<int, 3> expected = falseColour(std::max({d.r, d.g, d.b}) / scale);
      const std::array<int, 3> shown = window.at(int(x), int(y));
      for (int c = 0; c < 3; ++c) off += std::abs(shown[c] - expected[c]) > 2 ? 1 : 0;
      count += 3;
    }
  }
  EXPECT_EQ(off, 0u) << "of " << count << " channels the window's false colour is off by more than 2";
}

// Picking: `pick X Y` is a click on that image pixel. It selects the material the pixel sees (the lobe saved
// next is that material's) and reports the pixel's radiance and samples, which are the screenshot's.
TEST(CompareWindowTest, PickingAPixelSelectsItsMaterialAndReadsItsRadiance) {
  const std::string dir = scratchDir();
  const Scene scene = loadScene({kMinimalScene, ""});
  const std::vector<bool> ball = sphereMask(scene, "red plastic", kWidth, kHeight, 0.9f);
  ASSERT_TRUE(ball[std::size_t(128) * kWidth + 128]) << "pixel (128, 128) should see the ball";
  const std::string shot = dir + "/picked.exr";
  const std::string lobe = dir + "/picked_lobe.csv";
  fs::remove(lobe);
  const std::string script = writeScript("pick.txt",
                                         "at 2 screenshot " + shot + "\n"
                                         "at 2 pick 128 128\n"
                                         "at 2 save lobe " + lobe + "\n"
                                         "at 3 pick 4 250\n"
                                         "at 3 pick 128 1\n");
  const CommandResult result =
      runView({kMinimalScene, "--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--frames",
               "4", "--script", script});
  expectCleanRun(result);
  const std::size_t at = result.output.find("picked (128, 128): red plastic (cooktorrance), ");
  ASSERT_NE(at, std::string::npos) << result.output;
  EXPECT_NE(result.output.find("picked (4, 250): ground (lambert)"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("picked (128, 1): (background)"), std::string::npos) << result.output;

  std::istringstream line(result.output.substr(at + std::string("picked (128, 128): red plastic (cooktorrance), ").size()));
  glm::vec3 radiance;
  std::string samples;
  line >> radiance.r >> radiance.g >> radiance.b >> samples;
  EXPECT_EQ(samples, "(2") << "frames 0 and 1 each add one sample";
  const glm::vec4 pixel = readExr(shot).at(128, 128);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(radiance[c], pixel[c], 1e-5f * pixel[c] + 1e-7f) << "channel " << c;

  std::ifstream lobeFile(lobe);
  std::string header;
  std::getline(lobeFile, header);
  EXPECT_NE(header.find("cooktorrance"), std::string::npos) << "the lobe is not of the picked material: " << header;
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// The lobe file's directions, evaluated by `raylab brdf eval` on the device, give the lobe file's f exactly (the
// same kernel on the same float inputs), and fcos is f cos theta_o.
TEST(CompareWindowTest, LobePlotValuesEqualBrdfEvalOnTheDevice) {
  const std::string dir = scratchDir();
  const std::string lobe = dir + "/lobe.csv";
  const std::string script = writeScript("lobe.txt", "at 1 pick 128 128\nat 1 save lobe " + lobe + "\n");
  expectCleanRun(runView({kMinimalScene, "--width", std::to_string(kWidth), "--height", std::to_string(kHeight),
                          "--frames", "2", "--script", script}));
  std::ifstream file(lobe);
  std::string line;
  std::ostringstream cases;
  cases << "id,model,params,wi,wo,n,t\n";
  std::vector<std::vector<std::string>> rows;
  while (std::getline(file, line)) {
    const std::vector<std::string> fields = splitCsv(line);
    if (fields.empty() || fields[0] != "lobe") continue;
    ASSERT_EQ(fields.size(), 7u) << line;
    cases << rows.size() << ",cooktorrance,rho_d=0.6/0.1/0.1;rho_s=1;m=0.2;eta=1.5," << fields[3] << "," << fields[4]
          << ",0 0 1,1 0 0\n";
    rows.push_back(fields);
  }
  ASSERT_EQ(rows.size(), 181u);
  const std::string in = dir + "/lobe_cases.csv", out = dir + "/lobe_values.csv";
  std::ofstream(in) << cases.str();
  const CommandResult eval = runRaylab({"brdf", "eval", "--in", in, "--out", out});
  ASSERT_EQ(eval.exitCode, 0) << eval.output;
  std::ifstream values(out);
  std::getline(values, line);  // header
  std::size_t row = 0, nonZero = 0;
  while (std::getline(values, line)) {
    const std::vector<std::string> fields = splitCsv(line);
    ASSERT_EQ(fields.size(), 9u) << line;
    ASSERT_LT(row, rows.size());
    EXPECT_EQ(fields[8], rows[row][5]) << "theta_o " << rows[row][2];
    std::istringstream f(fields[8]), fcos(rows[row][6]), wo(rows[row][4]);
    glm::dvec3 fv, fcosv, wov;
    f >> fv.x >> fv.y >> fv.z;
    fcos >> fcosv.x >> fcosv.y >> fcosv.z;
    wo >> wov.x >> wov.y >> wov.z;
    EXPECT_NEAR(fcosv.x, fv.x * wov.z, 1e-6 * fv.x) << "theta_o " << rows[row][2];
    nonZero += fv.x > 0.0 ? 1 : 0;
    ++row;
  }
  EXPECT_EQ(row, rows.size());
  EXPECT_GT(nonZero, 170u) << "a lobe of zeros compares equal to anything";
}

// Bad --compare text: the message lists what exists, exit 2, and no window (DISPLAY is empty: opening one would
// fail with exit 1 and the X11 message instead).
TEST(CompareWindowTest, BadCompareTextListsWhatExistsAndExitsTwoBeforeAnyWindow) {
  const std::vector<std::string> noDisplay = {"DISPLAY=", "WAYLAND_DISPLAY="};
  const struct {
    std::string text;
    std::string expected;
  } cases[] = {
      {"nosuch=ward", "'ground', 'red plastic'"},
      {"red plastic=wardish", "lambert, phong, blinnphong"},
      {"red plastic=ward:alpha_x=-1", "alpha_x"},
      {"red plastic=ward:beta=1", "alpha_x"},
      {"red plastic=ward:alpha_x=nan", "expected a number"},
      {"", "empty"},
      {"red plastic", "MATERIAL=MODEL"},
  };
  for (const auto& c : cases) {
    const CommandResult view =
        runCommand({RAYLAB_BINARY, "view", kMinimalScene, "--frames", "1", "--compare", c.text}, noDisplay);
    EXPECT_EQ(view.exitCode, 2) << c.text << ": " << view.output;
    EXPECT_NE(view.output.find(c.expected), std::string::npos) << c.text << ": " << view.output;
    EXPECT_EQ(view.output.find("X11"), std::string::npos) << c.text << ": " << view.output;
    const CommandResult render = runRaylab({"render", kMinimalScene, "--no-png", "--out",
                                            scratchDir() + "/never.exr", "--material", c.text});
    EXPECT_EQ(render.exitCode, 2) << c.text << ": " << render.output;
  }
}

}  // namespace
}  // namespace raylab::test
