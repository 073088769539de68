// The raylab executable as users and scripts run it: help, usage errors, the no-device path, and a render
// that writes readable files.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "image/image.h"
#include "support/hostile_exr.h"
#include "support/run_command.h"

namespace raylab::test {
namespace {

std::string scratchDir() {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raylab_cli_test";
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(CliTest, EveryCommandHasHelp) {
  const CommandResult top = runRaylab({"--help"});
  EXPECT_EQ(top.exitCode, 0) << top.output;
  EXPECT_NE(top.output.find("render"), std::string::npos);
  EXPECT_NE(top.output.find("devices"), std::string::npos);
  for (const char* command : {"render", "devices"}) {
    const CommandResult help = runRaylab({command, "--help"});
    EXPECT_EQ(help.exitCode, 0) << command << ": " << help.output;
    EXPECT_NE(help.output.find("Usage: raylab " + std::string(command)), std::string::npos) << help.output;
  }
  const CommandResult render = runRaylab({"render", "--help"});
  for (const char* option : {"--width", "--height", "--spp", "--seed", "--out", "--png", "--exposure"}) {
    EXPECT_NE(render.output.find(option), std::string::npos) << option;
  }
}

TEST(CliTest, UsageErrorsExitTwoAndNameTheOption) {
  struct Case {
    std::vector<std::string> args;
    std::string mentions;
  };
  const Case cases[] = {
      {{"render", "--spp", "abc"}, "--spp"},
      {{"render", "--width", "0"}, "--width"},
      {{"render", "--exposure", "nan"}, "--exposure"},
      {{"render", "--bogus"}, "--bogus"},
      {{"render", "--height"}, "--height"},
      {{"render", "--out", "image.png"}, "--out"},
      {{"render", "--tonemap", "filmic"}, "--tonemap"},
      {{"render", "--integrator", "bidir"}, "--integrator"},
      {{"render", "--sampling", "stratified"}, "--sampling"},
      {{"render", "--backend", "optix"}, "--backend"},
      {{"render", "--heatmap", "cost.exr"}, "--heatmap"},
      {{"render", "--schedule", "streams"}, "--schedule"},
      {{"render", "--integrator", "slides", "--schedule", "wavefront"}, "--schedule wavefront"},
      {{"view", "--backend", "cuda"}, "--backend"},
      {{"sweep", "--model", "lambert", "--param", "rho_d", "--backend", "x"}, "--backend"},
      {{"render", "--env-strength", "-1"}, "--env-strength"},
      {{"render", "--env-strength", "nan"}, "--env-strength"},
      {{"render", "--env-strength", "2"}, "--env-strength: the scene has no environment image"},
      {{"view", "--env-strength", "inf"}, "--env-strength"},
      {{"frobnicate"}, "frobnicate"},
      {{}, "Usage"},
  };
  for (const Case& c : cases) {
    const CommandResult result = runRaylab(c.args);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << result.output;
  }
}

// Bad parameters of the second library's models in a --material override (the default scene's material
// 'phong'): exit 2, a message naming the material, the model, the parameter and its range, and nothing written.
TEST(CliTest, BadModelParametersNameTheMaterialParameterAndRangeAndWriteNothing) {
  const std::filesystem::path dir = std::filesystem::path(scratchDir()) / "bad_parameters";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "image.exr").string();
  const std::string png = (dir / "image.png").string();
  struct Case {
    std::string material;
    std::string mentions;
  };
  const Case cases[] = {
      {"phong=ggx_dielectric:eta=1", "'phong' (ggx_dielectric): eta = 1 is outside [1.001, 10]"},
      {"phong=ggx_dielectric:eta=0.5", "'phong' (ggx_dielectric): eta = 0.5 is outside [1.001, 10]"},
      {"phong=ggx_dielectric:alpha_x=nan", "'phong' (ggx_dielectric): alpha_x: expected a number, got 'nan'"},
      {"phong=ggx_conductor:k=-1", "'phong' (ggx_conductor): k = -1 is outside [0, 20]"},
      {"phong=ggx_conductor:metal=Unobtainium", "metal 'Unobtainium' is not one of ggx_conductor's (Ag, Al, Au, Cr, Cu)"},
      {"phong=gltf_pbr:ior=4", "'phong' (gltf_pbr): ior = 4 is outside [1, 3]"},
      {"phong=eon:r=2", "'phong' (eon): r = 2 is outside [0, 1]"},
      {"phong=openpbr:coat_weight=1.5", "'phong' (openpbr): coat_weight = 1.5 is outside [0, 1]"},
      {"phong=openpbr:fuzz_weight=-0.1", "'phong' (openpbr): fuzz_weight = -0.1 is outside [0, 1]"},
      {"phong=openpbr:transmission_depth=-1", "'phong' (openpbr): transmission_depth = -1 is outside [0, 1000]"},
      {"phong=openpbr:thin_film_weight=nan", "'phong' (openpbr): thin_film_weight: expected a number, got 'nan'"},
      {"phong=openpbr:geometry_opacity=2", "'phong' (openpbr): geometry_opacity = 2 is outside [0, 1]"},
  };
  for (const Case& c : cases) {
    const CommandResult result =
        runRaylab({"render", "--material", c.material, "--out", out, "--png", png, "--spp", "1", "--width", "8", "--height", "8"});
    EXPECT_EQ(result.exitCode, 2) << c.material << ": " << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.material;
    EXPECT_FALSE(std::filesystem::exists(png)) << c.material;
  }
}

// The same from a scene file: a glTF material's layer value out of its range, by an extension or by extras.raylab,
// exits 2 naming the material and the parameter, and writes nothing (issue 38).
TEST(CliTest, BadLayerValuesInASceneExitTwoNamingTheMaterialAndWriteNothing) {
  const std::filesystem::path dir = std::filesystem::path(scratchDir()) / "bad_scene_values";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ifstream in(std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/minimal.gltf");
  const std::string minimal((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string ground = "\"name\": \"ground\",\n      \"extras\"";
  ASSERT_NE(minimal.find(ground), std::string::npos);
  struct Case {
    std::string material;  // replaces the ground's extras
    std::string mentions;
  };
  const Case cases[] = {
      {"\"extensions\": {\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1.5}}, \"extras\"",
       "'ground': KHR_materials_clearcoat.clearcoatFactor = 1.5 is outside [0, 1]"},
      {"\"extensions\": {\"KHR_materials_dispersion\": {\"dispersion\": -1}}, \"extras\"",
       "'ground': KHR_materials_dispersion.dispersion = -1 is outside"},
      {"\"extras\": {\"raylab\": {\"model\": \"openpbr\", \"transmission_depth\": -1}}, \"unused\"",
       "'ground': extras.raylab: transmission_depth = -1 is outside [0, 1000]"},
  };
  const std::string out = (dir / "image.exr").string(), png = (dir / "image.png").string();
  for (const Case& c : cases) {
    std::string text = minimal;
    text.replace(text.find(ground), ground.size(), "\"name\": \"ground\", " + c.material);
    const std::string scene = (dir / "scene.gltf").string();
    std::ofstream(scene) << text;
    const CommandResult result = runRaylab({"render", scene, "--out", out, "--png", png, "--spp", "1", "--width", "8",
                                            "--height", "8"});
    EXPECT_EQ(result.exitCode, 2) << c.material << ": " << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.material;
    EXPECT_FALSE(std::filesystem::exists(png)) << c.material;
  }
}

// A missing, unreadable or non-finite environment image: exit 1, a message naming the file, and no output.
TEST(CliTest, ABadEnvironmentImageExitsOneNamingItAndWritesNothing) {
  const std::filesystem::path dir = std::filesystem::path(scratchDir()) / "environment";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  Image nan(4, 2);
  nan.set(3, 1, glm::vec4(1.0f, std::nanf(""), 0.0f, 1.0f));
  writeExrUnchecked((dir / "nan.exr").string(), nan);
  std::ofstream(dir / "text.exr") << "P3 1 1 255 0 0 0";
  const std::string out = (dir / "image.exr").string();
  const std::string png = (dir / "image.png").string();
  for (const char* name : {"missing.exr", "nan.exr", "text.exr"}) {
    const std::string file = (dir / name).string();
    const CommandResult result = runRaylab({"render", "--env", file, "--out", out, "--png", png, "--spp", "1"});
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("--env: environment image " + file), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(png));
  }
}

TEST(CliTest, WithoutAVulkanDriverEveryCommandExitsThreeWithOneClearSentence) {
  for (const char* command : {"render", "devices"}) {
    const CommandResult result = runRaylab({command}, {"VK_ICD_FILENAMES="});
    EXPECT_EQ(result.exitCode, 3) << command << ": " << result.output;
    EXPECT_NE(result.output.find("tools/setup.sh"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("lavapipe with ray tracing"), std::string::npos) << result.output;
  }
}

TEST(CliTest, DevicesListsTheCapableDevice) {
  const CommandResult result = runRaylab({"devices"});
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("raylab: yes"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("driver:"), std::string::npos) << result.output;
  // Both ray-tracing interfaces are listed, and the backends raylab runs with them.
  EXPECT_NE(result.output.find("ray queries: yes; ray-tracing pipelines: yes"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("raylab: yes (backends: query, pipeline; auto: query)"), std::string::npos)
      << result.output;
}

// A device with ray-tracing pipelines but no ray queries (NVIDIA's data-centre GPUs), simulated by hiding
// lavapipe's ray queries: capable, `auto` takes the pipeline, and the image is the ray-query backend's.
TEST(CliTest, ADeviceWithPipelinesOnlyRendersWithAuto) {
  const std::vector<std::string> hidden = {"RAYLAB_HIDE_RAY_QUERIES=1"};
  const CommandResult devices = runRaylab({"devices"}, hidden);
  EXPECT_EQ(devices.exitCode, 0) << devices.output;
  EXPECT_NE(devices.output.find("ray queries: hidden"), std::string::npos) << devices.output;
  EXPECT_NE(devices.output.find("raylab: yes (backends: pipeline; auto: pipeline)"), std::string::npos)
      << devices.output;

  const std::string dir = scratchDir();
  const std::vector<std::string> common = {"render", "--width", "40", "--height", "24", "--spp", "2", "--no-png",
                                           "--stats"};
  std::vector<std::string> pipelineArgs = common;
  pipelineArgs.insert(pipelineArgs.end(), {"--out", dir + "/hidden_auto.exr"});
  const CommandResult pipeline = runRaylab(pipelineArgs, hidden);
  ASSERT_EQ(pipeline.exitCode, 0) << pipeline.output;
  EXPECT_NE(pipeline.output.find("backend: pipeline"), std::string::npos) << pipeline.output;
  std::vector<std::string> queryArgs = common;
  queryArgs.insert(queryArgs.end(), {"--out", dir + "/query_auto.exr"});
  const CommandResult query = runRaylab(queryArgs);
  ASSERT_EQ(query.exitCode, 0) << query.output;
  EXPECT_NE(query.output.find("backend: query"), std::string::npos) << query.output;
  EXPECT_EQ(readExr(dir + "/hidden_auto.exr").rgba, readExr(dir + "/query_auto.exr").rgba);

  // Asking for what the device lacks is the no-device exit, naming the option and what to use instead.
  std::vector<std::string> forced = common;
  forced.insert(forced.end(), {"--backend", "query", "--out", dir + "/never.exr"});
  const CommandResult refused = runRaylab(forced, hidden);
  EXPECT_EQ(refused.exitCode, 3) << refused.output;
  EXPECT_NE(refused.output.find("--backend query"), std::string::npos) << refused.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/never.exr"));
}

TEST(CliTest, RenderWritesExrAndPngAndReportsTimings) {
  const std::string dir = scratchDir();
  const std::string exr = dir + "/nested/default.exr";
  const std::string png = dir + "/nested/default.png";
  std::filesystem::remove_all(dir + "/nested");
  const CommandResult result =
      runRaylab({"render", "--width", "48", "--height", "32", "--spp", "3", "--out", exr, "--png", png}, {},
                dir);  // nested/ is created below the working directory
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* line : {"3/3 spp", "rays/s", "acceleration structures:", "first sample:", "per sample:"}) {
    EXPECT_NE(result.output.find(line), std::string::npos) << "missing '" << line << "' in:\n" << result.output;
  }
  // The kernel's compilation is announced before the first sample waits for it, and the first progress line says
  // what it includes instead of a rate over the compilation (32-49 s of silence, then "1/64 spp 47.28 s 5.0 krays/s").
  const std::size_t compiling = result.output.find("raylab render: compiling the render kernel");
  EXPECT_NE(compiling, std::string::npos) << result.output;
  EXPECT_LT(compiling, result.output.find("1/3 spp")) << result.output;
  EXPECT_NE(result.output.find("1/3 spp"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("(first sample: kernel compilation included)"), std::string::npos) << result.output;
  const Image image = readExr(exr);
  EXPECT_EQ(image.width, 48u);
  EXPECT_EQ(image.height, 32u);
  float brightest = 0.0f;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) brightest = std::max(brightest, image.rgba[i]);
  EXPECT_GT(brightest, 0.05f) << "the default scene rendered black";
  EXPECT_GT(std::filesystem::file_size(png), 100u);
}

// The tests run lavapipe with 128-bit vectors (LP_NATIVE_VECTOR_WIDTH=128, tests/CMakeLists.txt), and all but the
// runtime-bound ones with LLVM's optimisation passes off (GALLIVM_PERF=nopt): a cold suite compiles in about half
// the time. That is only sound while the images do not depend on either: the same scenes under the driver's defaults
// (256-bit vectors on AVX2 machines, optimised) and under the tests' settings give the same pixels, bit for bit (the
// GLSL's arithmetic is per lane and LLVM keeps IEEE semantics; what the settings change is how many lanes run at
// once, the subgroup size, and how fast the code runs).
TEST(CliTest, ImagesDoNotDependOnTheDriverSettingsTheTestsUse) {
  const std::string dir = scratchDir();
  for (const char* scene : {"showcase_modern", "showcase"}) {
    std::vector<float> pixels[2];
    const std::vector<std::string> settings[2] = {{"LP_NATIVE_VECTOR_WIDTH=256", "GALLIVM_PERF="},
                                                  {"LP_NATIVE_VECTOR_WIDTH=128", "GALLIVM_PERF=nopt"}};
    for (int k = 0; k < 2; ++k) {
      const std::string exr = dir + "/driver_settings_" + std::to_string(k) + ".exr";
      const CommandResult result =
          runRaylab({"render", std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/" + scene + ".gltf", "--width", "64",
                     "--height", "48", "--spp", "2", "--out", exr, "--no-png"},
                    settings[k]);
      ASSERT_EQ(result.exitCode, 0) << scene << " with " << settings[k][0] << ":\n" << result.output;
      pixels[k] = readExr(exr).rgba;
    }
    ASSERT_EQ(pixels[0].size(), pixels[1].size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < pixels[0].size(); ++i) differing += std::memcmp(&pixels[0][i], &pixels[1][i], 4) != 0;
    EXPECT_EQ(differing, 0u) << scene << ": " << differing
                             << " channel values differ between the driver's defaults and the tests' settings";
  }
}

// The cost map: a false-colour PNG and the raw clock ticks per sample beside it, positive where the scene is,
// and the image itself unchanged by the clock.
TEST(CliTest, HeatmapWritesTheCostOfEveryPixel) {
  const std::string dir = scratchDir();
  std::filesystem::remove(dir + "/cost.png");
  std::filesystem::remove(dir + "/cost.exr");
  const std::vector<std::string> common = {"render", "--width", "40", "--height", "24", "--spp", "2", "--no-png"};
  std::vector<std::string> clocked = common;
  clocked.insert(clocked.end(), {"--out", dir + "/clocked.exr", "--heatmap", dir + "/cost.png"});
  const CommandResult result = runRaylab(clocked);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_GT(std::filesystem::file_size(dir + "/cost.png"), 100u);
  const Image ticks = readExr(dir + "/cost.exr");
  ASSERT_EQ(ticks.width, 40u);
  ASSERT_EQ(ticks.height, 24u);
  // Every pixel is written (never negative or NaN) and nearly all took time: on a machine whose hypervisor took
  // most of each core, a fresh clone's run once read the same clock at both ends of 4 of the 960 pixels' samples.
  std::size_t positive = 0, written = 0;
  for (std::size_t i = 0; i < ticks.rgba.size(); i += 4) {
    positive += ticks.rgba[i] > 0.0f;
    written += ticks.rgba[i] >= 0.0f;
  }
  EXPECT_EQ(written, std::size_t(40 * 24)) << "every pixel has a cost";
  EXPECT_GE(positive, std::size_t(40 * 24 * 99 / 100)) << "nearly every pixel took some time";
  // Per sample and plausible: a clock read behind its start used to wrap to about 1e19 ticks.
  float most = 0.0f;
  for (std::size_t i = 0; i < ticks.rgba.size(); i += 4) most = std::max(most, ticks.rgba[i]);
  EXPECT_LT(most, 1e10f) << "a pixel's cost per sample is beyond ten seconds of clock";
  std::vector<std::string> plain = common;
  plain.insert(plain.end(), {"--out", dir + "/plain.exr"});
  ASSERT_EQ(runRaylab(plain).exitCode, 0);
  EXPECT_EQ(readExr(dir + "/clocked.exr").rgba, readExr(dir + "/plain.exr").rgba);
}

// Mean over pixels and channels of (a - b)^2 / (b^2 + 0.01), each clamped at 1 first: the error as a user sees it.
double clampedRelMse(const Image& a, const Image& b) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double x = std::min(a.rgba[i], 1.0f), y = std::min(b.rgba[i], 1.0f);
    sum += (x - y) * (x - y) / (y * y + 0.01);
    ++n;
  }
  return sum / double(n);
}

// --denoise: the raw image as without it, the denoised one beside it (EXR and PNG), and the albedo and normal that
// guided it; the denoised image finite, of the same size, and closer to a converged render than the raw one.
TEST(CliTest, DenoiseWritesTheDenoisedImageAndItsGuidesBesideTheRawImage) {
  const std::string dir = scratchDir();
  for (const char* name : {"d.exr", "d.png", "d.denoised.exr", "d.denoised.png", "d.albedo.exr", "d.normal.exr"}) {
    std::filesystem::remove(dir + "/" + name);
  }
  const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/cornell_box_area.gltf";
  const std::vector<std::string> common = {"render", scene, "--width", "64", "--height", "48", "--no-png"};
  std::vector<std::string> denoised = {"render", scene, "--width", "64", "--height", "48", "--spp", "4", "--denoise",
                                       "--denoise-quality", "balanced", "--out", dir + "/d.exr", "--png", dir + "/d.png"};
  const CommandResult result = runRaylab(denoised);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("denoised: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("balanced quality"), std::string::npos) << result.output;
  for (const char* name : {"d.png", "d.denoised.png"}) EXPECT_GT(std::filesystem::file_size(dir + "/" + name), 100u);
  const Image raw = readExr(dir + "/d.exr"), clean = readExr(dir + "/d.denoised.exr");
  const Image albedo = readExr(dir + "/d.albedo.exr"), normal = readExr(dir + "/d.normal.exr");
  for (const Image* image : {&clean, &albedo, &normal}) {
    ASSERT_EQ(image->width, 64u);
    ASSERT_EQ(image->height, 48u);
    for (float v : image->rgba) ASSERT_TRUE(std::isfinite(v));
  }
  for (std::size_t i = 0; i < albedo.rgba.size(); ++i) {
    ASSERT_GE(albedo.rgba[i], 0.0f);
    ASSERT_LE(albedo.rgba[i], 1.0f);
  }
  // The raw image is the one a render without --denoise writes, bit for bit.
  std::vector<std::string> plain = common;
  plain.insert(plain.end(), {"--spp", "4", "--out", dir + "/plain.exr"});
  ASSERT_EQ(runRaylab(plain).exitCode, 0);
  EXPECT_EQ(readExr(dir + "/plain.exr").rgba, raw.rgba);
  // Four samples denoised are nearer a 256-sample render than four raw ones (measured: 7x nearer in clamped relMSE).
  std::vector<std::string> converged = common;
  converged.insert(converged.end(), {"--spp", "256", "--out", dir + "/converged.exr"});
  ASSERT_EQ(runRaylab(converged).exitCode, 0);
  const Image reference = readExr(dir + "/converged.exr");
  EXPECT_LT(clampedRelMse(clean, reference), 0.5 * clampedRelMse(raw, reference));
}

// Without Open Image Denoise --denoise stops before rendering: exit 2, saying how to install it, nothing written;
// without --denoise nothing needs the library.
TEST(CliTest, DenoiseWithoutTheLibraryExitsTwoSayingHowToInstallIt) {
  const std::string dir = scratchDir();
  std::filesystem::remove(dir + "/nolib.exr");
  const std::vector<std::string> missing = {"RAYLAB_OIDN_LIBRARY=" + dir + "/no/libOpenImageDenoise.so.2"};
  const CommandResult result = runRaylab(
      {"render", "--width", "16", "--height", "16", "--spp", "1", "--denoise", "--out", dir + "/nolib.exr", "--no-png"},
      missing);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("pyoidn"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("RAYLAB_OIDN_LIBRARY"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("compiling the render kernel"), std::string::npos) << "refused after rendering";
  EXPECT_FALSE(std::filesystem::exists(dir + "/nolib.exr"));
  const CommandResult plain =
      runRaylab({"render", "--width", "16", "--height", "16", "--spp", "1", "--out", dir + "/nolib.exr", "--no-png"},
                missing);
  EXPECT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_EQ(runRaylab({"render", "--denoise", "--denoise-quality", "best"}).exitCode, 2);
}

// `raylab info` names what the other commands take: cameras, materials with model and parameters, lights.
TEST(CliTest, InfoListsTheScenesNames) {
  const CommandResult result = runRaylab({"info", std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/minimal.gltf"});
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (const char* text : {"cameras (1): 'camera' (used)", "'red plastic': ", "'ground': lambert rho_d=",
                           "'lamp': point at", "spheres (1):", "material 'red plastic'"}) {
    EXPECT_NE(result.output.find(text), std::string::npos) << text << "\n" << result.output;
  }
  const CommandResult wrong =
      runRaylab({"info", std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/minimal.gltf", "--camera", "nope"});
  EXPECT_EQ(wrong.exitCode, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("cameras: 'camera'"), std::string::npos) << wrong.output;
}

TEST(CliTest, ErrorsCarryOnePrefixAndBareBrdfSaysWhatIsMissing) {
  const CommandResult usage = runRaylab({"render", "--spp", "abc"});
  EXPECT_EQ(usage.output.find("raylab: raylab"), std::string::npos) << usage.output;
  const CommandResult missing = runRaylab({"render", "/nonexistent/scene.gltf"});
  EXPECT_EQ(missing.exitCode, 1) << missing.output;
  EXPECT_NE(missing.output.find("raylab render: /nonexistent/scene.gltf: no such file"), std::string::npos)
      << missing.output;
  const CommandResult brdf = runRaylab({"brdf"});
  EXPECT_EQ(brdf.exitCode, 2) << brdf.output;
  EXPECT_NE(brdf.output.find("which subcommand"), std::string::npos) << brdf.output;
  const CommandResult top = runRaylab({"--help"});
  EXPECT_NE(top.output.find("brdf albedo"), std::string::npos) << top.output;
}

// `raylab render /dev/zero` used to read until memory ran out.
TEST(CliTest, ASceneThatIsNotARegularFileIsRefused) {
  for (const char* path : {"/dev/zero", "/tmp"}) {
    const CommandResult result = runRaylab({"render", path, "--no-png", "--out", "/tmp/raylab_cli_never.exr"});
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find(path), std::string::npos) << result.output;
  }
}

// Messages a user trips over (issue 21): each names what was wrong, with a usage exit where the command line was.
TEST(CliTest, MessagesSayWhatWasWrong) {
  const std::string cameras = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
  const std::string dir = scratchDir();
  if (std::filesystem::exists(cameras)) {
    // The orthographic camera by the name `raylab info` lists it under: "is orthographic", not "no camera".
    const CommandResult orthographic = runRaylab({"render", cameras, "--camera", "camera 1", "--no-png", "--out",
                                                 dir + "/never.exr"});
    EXPECT_EQ(orthographic.exitCode, 1) << orthographic.output;
    EXPECT_NE(orthographic.output.find("camera 'camera 1' is orthographic"), std::string::npos) << orthographic.output;
    std::filesystem::copy_file(cameras, dir + "/scene.obj", std::filesystem::copy_options::overwrite_existing);
    const CommandResult obj = runRaylab({"render", dir + "/scene.obj", "--no-png", "--out", dir + "/never.exr"});
    EXPECT_EQ(obj.exitCode, 2) << obj.output;
    EXPECT_NE(obj.output.find("raylab reads glTF 2.0 scenes (.gltf or .glb), not '.obj'"), std::string::npos)
        << obj.output;
  }
  const CommandResult typo = runRaylab({"render", "--sppp", "3"});
  EXPECT_EQ(typo.exitCode, 2) << typo.output;
  EXPECT_NE(typo.output.find("(did you mean --spp?)"), std::string::npos) << typo.output;
  for (const char* option : {"--env", "--camera", "--out"}) {
    const CommandResult empty = runRaylab({"render", option, ""});
    EXPECT_EQ(empty.exitCode, 2) << option << ": " << empty.output;
    EXPECT_NE(empty.output.find(std::string(option) + ": is empty"), std::string::npos) << empty.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/never.exr"));
}

}  // namespace
}  // namespace raylab::test
