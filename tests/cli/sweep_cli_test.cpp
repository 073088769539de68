// `raylab sweep` as users run it: a tiny contact sheet end to end (files, sizes, labels in the PNG only, cells
// brighter along a rho_d sweep), the scene written with --gltf loads back, and usage errors exit 2 naming the
// option and, for values, the accepted range.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf_params/material_params.h"
#include "image/contact_sheet.h"
#include "image/image.h"
#include "gltf_read/gltf_loader.h"
#include "sweep/sweep_scene.h"
#include "support/run_command.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

std::string scratchDir() {
  const fs::path dir = fs::temp_directory_path() / "raylab_sweep_cli_test";
  fs::create_directories(dir);
  return dir.string();
}

// The layout the command must have used: the same title and labels from the same sweep.
ContactSheetLayout expectedLayout(const SweepSpec& spec, std::uint32_t cell) {
  const SweepScene sweep = makeSweepScene(spec);
  std::vector<std::string> labels;
  for (std::uint32_t i = 0; i < sweep.values.size(); ++i) labels.push_back(sweepLabel(sweep, i));
  return layoutContactSheet(spec.steps, cell, sweepTitle(sweep), labels);
}

double cellMean(const Image& image, const ContactSheetLayout& layout, std::uint32_t index) {
  const glm::uvec2 origin = layout.cellOrigin(index);
  double sum = 0.0;
  for (std::uint32_t y = 0; y < layout.cellSize; ++y) {
    for (std::uint32_t x = 0; x < layout.cellSize; ++x) {
      const glm::vec4 pixel = image.at(origin.x + x, origin.y + y);
      sum += pixel.r + pixel.g + pixel.b;
    }
  }
  return sum / (3.0 * layout.cellSize * layout.cellSize);
}

// How many pixels of the band above the first row of cells are not black: the title's.
int titlePixels(const unsigned char* rgb, const ContactSheetLayout& layout) {
  int lit = 0;
  for (std::uint32_t i = 0; i < layout.titleHeight * layout.width * 3; ++i) lit += rgb[i] > 0 ? 1 : 0;
  return lit;
}

TEST(SweepCliTest, HelpListsTheOptions) {
  const CommandResult help = runRaylab({"sweep", "--help"});
  ASSERT_EQ(help.exitCode, 0) << help.output;
  for (const char* option : {"--model", "--param", "--from", "--to", "--steps", "--log", "--set", "--out", "--cell",
                             "--spp", "--seed", "--exposure", "--tonemap", "--device", "--gltf"}) {
    EXPECT_NE(help.output.find(option), std::string::npos) << option << " missing from:\n" << help.output;
  }
  const CommandResult top = runRaylab({"--help"});
  EXPECT_NE(top.output.find("sweep"), std::string::npos) << top.output;
}

TEST(SweepCliTest, RhoDSweepWritesALabelledSheetWhoseCellsGetBrighter) {
  const std::string dir = scratchDir() + "/nested";
  fs::remove_all(dir);
  const std::string png = dir + "/rho_d.png";
  const std::string exr = dir + "/rho_d.exr";
  const CommandResult result =
      runRaylab({"sweep", "--model", "lambert", "--param", "rho_d", "--from", "0.1", "--to", "0.9", "--steps", "3",
                 "--cell", "32", "--spp", "2", "--out", png},
                {}, scratchDir());  // nested/ is created below the working directory
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // The sheet's samples over all its cells, said as such ("6/6 spp" read as 6 samples per pixel).
  EXPECT_NE(result.output.find("6/6 samples (2 spp x 3 cells)"), std::string::npos) << "no progress line in:\n"
                                                                                      << result.output;
  EXPECT_NE(result.output.find("lambert: rho_d from 0.1 to 0.9"), std::string::npos) << result.output;

  SweepSpec spec;
  spec.model = "lambert";
  spec.param = "rho_d";
  spec.from = 0.1f;
  spec.to = 0.9f;
  spec.steps = 3;
  const ContactSheetLayout layout = expectedLayout(spec, 32);
  const Image linear = readExr(exr);
  ASSERT_EQ(linear.width, layout.width);
  ASSERT_EQ(linear.height, layout.height);
  int width = 0, height = 0, channels = 0;
  unsigned char* rgb = stbi_load(png.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(rgb, nullptr) << png << ": " << stbi_failure_reason();
  EXPECT_EQ(std::uint32_t(width), layout.width);
  EXPECT_EQ(std::uint32_t(height), layout.height);
  // Text goes into the PNG only; the EXR holds radiance, black around the cells.
  EXPECT_GT(titlePixels(rgb, layout), 20) << "the PNG has no title";
  stbi_image_free(rgb);
  for (std::uint32_t y = 0; y < layout.titleHeight; ++y) {
    for (std::uint32_t x = 0; x < layout.width; ++x) ASSERT_EQ(linear.at(x, y).r, 0.0f) << "text in the EXR";
  }

  double previous = -1.0;
  for (std::uint32_t i = 0; i < 3; ++i) {
    const double mean = cellMean(linear, layout, i);
    EXPECT_TRUE(std::isfinite(mean));
    EXPECT_GT(mean, previous) << "cell " << i << " is not brighter than cell " << i - 1;
    previous = mean;
  }
}

TEST(SweepCliTest, GltfWritesTheRowAsALoadableScene) {
  const std::string gltf = scratchDir() + "/phong_s.gltf";
  fs::remove(gltf);
  const CommandResult result = runRaylab({"sweep", "--model", "phong", "--param", "s", "--from", "1", "--to", "100",
                                          "--steps", "3", "--set", "rho_d=0.2/0.1/0.05", "--gltf", gltf});
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_FALSE(fs::exists(scratchDir() + "/phong_s.png")) << "--gltf alone must not render";
  const Scene scene = loadGltfFile(gltf, {});
  ASSERT_EQ(scene.spheres.size(), 3u);
  EXPECT_EQ(scene.camera.name, "camera") << "the overview of the whole row comes first";
  EXPECT_EQ(loadGltfFile(gltf, {"row"}).camera.name, "row");
  ASSERT_EQ(scene.lights.size(), 1u);
  const float expected[] = {1.0f, 10.0f, 100.0f};  // geometric, the default for an exponent
  for (std::size_t i = 0; i < 3; ++i) {
    const gpu::MaterialRecord& record = scene.materials.at(scene.spheres[i].material).record;
    EXPECT_EQ(record.model, modelId("phong"));
    EXPECT_NEAR(getParam(record, "s").x, expected[i], 1e-4f * expected[i]);
    EXPECT_NEAR(getParam(record, "rho_d").r, 0.2f, 1e-6f);
    EXPECT_NEAR(getParam(record, "rho_d").b, 0.05f, 1e-6f);
  }
}

TEST(SweepCliTest, ANamedMetalSetsItsParameters) {
  const std::string gltf = scratchDir() + "/gold.gltf";
  fs::remove(gltf);
  const CommandResult result = runRaylab({"sweep", "--model", "ggx_conductor", "--param", "alpha_x", "--steps", "2",
                                          "--set", "metal=Au", "--set", "alpha_y=0.05", "--gltf", gltf});
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const Scene scene = loadGltfFile(gltf, {});
  ASSERT_EQ(scene.spheres.size(), 2u);
  for (const Sphere& sphere : scene.spheres) {
    const gpu::MaterialRecord& record = scene.materials.at(sphere.material).record;
    EXPECT_NEAR(getParam(record, "eta").b, 1.44205f, 1e-5f) << "Au's eta";
    EXPECT_NEAR(getParam(record, "k").r, 3.983f, 1e-5f) << "Au's k";
    EXPECT_NEAR(getParam(record, "alpha_y").x, 0.05f, 1e-7f);
    const glm::vec3 preview = previewColour(record);
    EXPECT_TRUE(glm::all(glm::lessThanEqual(preview, glm::vec3(1.0f)))) << "glTF's baseColorFactor holds a colour";
  }
}

TEST(SweepCliTest, UsageErrorsExitTwoAndNameTheOptionAndRange) {
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> mentions;
  };
  const std::vector<std::string> phongS = {"sweep", "--model", "phong", "--param", "s"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = phongS;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const Case cases[] = {
      {{"sweep", "--param", "s"}, {"--model"}},
      {{"sweep", "--model", "plastic", "--param", "s"}, {"--model", "plastic", "cooktorrance"}},
      {{"sweep", "--model", "phong", "--param", "m"}, {"--param", "'m'", "rho_s"}},
      {with({"--from", "0.5"}), {"--from", "[1, 10000]"}},
      {with({"--to", "20000"}), {"--to", "[1, 10000]"}},
      {with({"--from", "nan"}), {"--from", "nan"}},
      {with({"--to", "inf"}), {"--to"}},
      {{"sweep", "--model", "lambert", "--param", "rho_d", "--log"}, {"--from", "--log"}},
      {{"sweep", "--model", "lambert", "--param", "rho_d", "--to", "1.5"}, {"--to", "[0, 1]"}},
      {with({"--steps", "1"}), {"--steps"}},
      {with({"--set", "rho_d=2"}), {"--set rho_d", "[0, 1]"}},
      {with({"--set", "rho_d=0.1/0.2"}), {"--set rho_d"}},
      {with({"--set", "s=5"}), {"--set s", "swept"}},
      {with({"--set", "m=0.1"}), {"--set", "'m'"}},
      {with({"--set", "rho_s"}), {"--set", "K=V"}},
      {with({"--set"}), {"--set"}},
      {with({"--set", "rho_s=nan"}), {"--set rho_s", "nan"}},
      {with({"--out", "sheet.tif"}), {"--out", ".exr"}},
      {with({"--png", "sheet.exr"}), {"--png", ".png"}},
      {with({"--out", "a.png", "--png", "b.png"}), {"--out", "is the EXR"}},
      {with({"--cell", "0"}), {"--cell"}},
      {with({"--tonemap", "filmic"}), {"--tonemap"}},
      // Named sets of values (presets): an unknown name lists the known ones; one that sets the swept parameter is
      // refused like --set of it.
      {{"sweep", "--model", "ggx_conductor", "--param", "alpha_x", "--set", "metal=Xx"},
       {"--set metal", "'Xx'", "Ag, Al, Au, Cr, Cu"}},
      {{"sweep", "--model", "ggx_conductor", "--param", "eta", "--set", "metal=Au"}, {"--set metal", "eta", "swept"}},
  };
  for (const Case& c : cases) {
    const CommandResult result = runRaylab(c.args);
    std::string command;
    for (const std::string& arg : c.args) command += " " + arg;
    EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output;
    for (const std::string& text : c.mentions) {
      EXPECT_NE(result.output.find(text), std::string::npos)
          << command << ": no '" << text << "' in\n" << result.output;
    }
  }
}

// --out is the EXR and --png the PNG, as in `raylab render`; either alone puts the other beside it, and the old
// spelling --out FILE.png is still taken as --png.
TEST(SweepCliTest, OutIsTheExrAndPngThePngAsInRender) {
  const std::string dir = scratchDir() + "/spellings";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::string> sweep = {"sweep", "--model", "lambert", "--param", "rho_d", "--steps", "2",
                                          "--cell", "16", "--spp", "1"};
  const auto run = [&](std::vector<std::string> outputs) {
    std::vector<std::string> args = sweep;
    args.insert(args.end(), outputs.begin(), outputs.end());
    const CommandResult result = runRaylab(args);
    EXPECT_EQ(result.exitCode, 0) << result.output;
  };
  run({"--out", dir + "/a.exr"});
  EXPECT_TRUE(fs::exists(dir + "/a.exr") && fs::exists(dir + "/a.png"));
  run({"--png", dir + "/b.png"});
  EXPECT_TRUE(fs::exists(dir + "/b.exr") && fs::exists(dir + "/b.png"));
  run({"--out", dir + "/c.exr", "--png", dir + "/d.png"});
  EXPECT_TRUE(fs::exists(dir + "/c.exr") && fs::exists(dir + "/d.png") && !fs::exists(dir + "/c.png"));
  run({"--out", dir + "/e.png"});
  EXPECT_TRUE(fs::exists(dir + "/e.exr") && fs::exists(dir + "/e.png"));
  EXPECT_EQ(readExr(dir + "/a.exr").rgba, readExr(dir + "/e.exr").rgba);
}

}  // namespace
}  // namespace raylab::test
