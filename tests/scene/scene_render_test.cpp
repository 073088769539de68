// Renders of the committed scenes and of real glTF files: no NaN or Inf pixel, something lit, and along
// every sweep's row the brightness order that the scene's extras.sweep states (tools/scenes/make_scenes.py
// explains each). With RAYLAB_TEST_IMAGES=DIR set, every render is also written to DIR as a PNG.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "gltf_test_support.h"
#include "render/renderer.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

class SceneRenderTest : public GpuTest {};

// The sweeps are measured at 16:9, the aspect their cameras frame; the window is the disc of a quarter of
// each sphere's projected radius around its projected centre.
constexpr std::uint32_t kSweepWidth = 320;
constexpr std::uint32_t kSweepHeight = 180;
constexpr std::uint32_t kSweepSpp = 8;
constexpr float kWindowFraction = 0.25f;
constexpr std::size_t kMinWindowPixels = 20;
// Tolerances relative to the row's brightest window: a step may go the wrong way by this much (sampling
// noise of the jittered pixels), and the row must change by at least kMinChange end to end.
constexpr float kStepTolerance = 0.01f;
constexpr float kMinChange = 0.2f;

Image render(const Device& device, const Scene& scene, std::uint32_t width, std::uint32_t height, std::uint32_t spp) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  return renderImage(device, scene, settings, spp);
}

void saveForInspection(const Image& image, const std::string& name) {
  const char* directory = std::getenv("RAYLAB_TEST_IMAGES");
  if (directory != nullptr && *directory != '\0') {
    writePng((fs::path(directory) / (name + ".png")).string(), image, 0.0f, ToneMap::kClamp);
  }
}

// Expects every pixel finite and some pixel lit.
void expectSaneImage(const Image& image, const std::string& name) {
  std::size_t nonFinite = 0;
  float brightest = 0.0f;
  for (float value : image.rgba) {
    if (!std::isfinite(value)) ++nonFinite;
    else brightest = std::max(brightest, value);
  }
  EXPECT_EQ(nonFinite, 0u) << name << ": NaN or Inf pixel values";
  EXPECT_GT(brightest, 0.0f) << name << ": the image is black";
}

Scene loadQuietly(const fs::path& path) {
  WarningCapture warnings;  // the loader tests check the warnings; here they would only clutter the log
  return loadGltfFile(path.string(), {});
}

TEST_F(SceneRenderTest, EveryCommittedSceneRendersFinite) {
  const std::vector<fs::path> files = assetFiles();
  ASSERT_FALSE(files.empty()) << "no scenes in " << assetsDirectory() << ": run tools/scenes/make_scenes.py";
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Image image = render(device(), loadQuietly(file), 64, 48, 2);
    saveForInspection(image, file.stem().string());
    expectSaneImage(image, file.stem().string());
  }
}

TEST_F(SceneRenderTest, RealGltfFilesRenderFinite) {
  ASSERT_TRUE(fs::is_directory(assimpDirectory()))
      << assimpDirectory() << " is missing: install the assimp-testmodels package (run tools/setup.sh test)";
  for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                           "2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                           "BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "cameras/Cameras.gltf"}) {
    SCOPED_TRACE(file);
    const Image image = render(device(), loadQuietly(assimpDirectory() / file), 64, 48, 2);
    saveForInspection(image, fs::path(file).stem().string() + "_" + fs::path(file).extension().string().substr(1));
    expectSaneImage(image, file);
  }
}

struct Window {
  float mean = 0.0f;  // of (r + g + b) / 3
  std::size_t pixels = 0;
};

// The mean radiance over the pixels whose centres lie within kWindowFraction of the sphere's projected
// radius from its projected centre, projecting as applyCamera sets the kernel's camera up.
Window measureWindow(const Image& image, const Scene& scene, const Sphere& sphere) {
  gpu::FrameParams params{};
  applyCamera(params, scene.camera, image.width, image.height);
  const glm::vec3 toCenter = sphere.center - params.cameraOrigin;
  const float depth = glm::dot(toCenter, params.cameraForward);
  // A ray through NDC (x, y) has direction forward + x right + y up (render.comp).
  const float ndcX = glm::dot(toCenter, params.cameraRight) / glm::dot(params.cameraRight, params.cameraRight) / depth;
  const float ndcY = glm::dot(toCenter, params.cameraUp) / glm::dot(params.cameraUp, params.cameraUp) / depth;
  const float centerX = 0.5f * (ndcX + 1.0f) * float(image.width);
  const float centerY = 0.5f * (1.0f - ndcY) * float(image.height);
  const float radiusPixels = sphere.radius / (depth * glm::length(params.cameraUp)) * 0.5f * float(image.height);
  const float windowRadius = kWindowFraction * radiusPixels;

  Window window;
  double sum = 0.0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const float dx = float(x) + 0.5f - centerX;
      const float dy = float(y) + 0.5f - centerY;
      if (dx * dx + dy * dy > windowRadius * windowRadius) continue;
      const glm::vec4 pixel = image.at(x, y);
      sum += (pixel.r + pixel.g + pixel.b) / 3.0;
      ++window.pixels;
    }
  }
  window.mean = window.pixels > 0 ? float(sum / double(window.pixels)) : 0.0f;
  return window;
}

TEST_F(SceneRenderTest, SweepsShowTheirBrightnessOrderAlongTheRow) {
  int sweeps = 0;
  for (const fs::path& file : assetFiles()) {
    std::ifstream in(file);
    const nlohmann::json doc = nlohmann::json::parse(in);
    const nlohmann::json& extras = doc["scenes"][0].value("extras", nlohmann::json::object());
    if (!extras.contains("sweep")) continue;
    ++sweeps;
    const std::string name = file.stem().string();
    const bool increasing = extras["sweep"]["brightness"] == "increasing";
    SCOPED_TRACE(name + " (" + extras["sweep"]["brightness"].get<std::string>() + ": " +
                 extras["sweep"]["why"].get<std::string>() + ")");

    Scene scene = loadQuietly(file);
    std::sort(scene.spheres.begin(), scene.spheres.end(),
              [](const Sphere& a, const Sphere& b) { return a.center.x < b.center.x; });
    const Image image = render(device(), scene, kSweepWidth, kSweepHeight, kSweepSpp);
    saveForInspection(image, name + "_sweep");
    expectSaneImage(image, name);

    std::vector<float> means;
    std::string row;
    for (const Sphere& sphere : scene.spheres) {
      const Window window = measureWindow(image, scene, sphere);
      ASSERT_GE(window.pixels, kMinWindowPixels) << "the window is too small to measure";
      means.push_back(window.mean);
      char shown[32];
      std::snprintf(shown, sizeof shown, " %.4g", window.mean);
      row += shown;
    }
    const float brightest = *std::max_element(means.begin(), means.end());
    ASSERT_GT(brightest, 0.0f) << "every window is black:" << row;
    for (std::size_t i = 1; i < means.size(); ++i) {
      const float step = increasing ? means[i] - means[i - 1] : means[i - 1] - means[i];
      EXPECT_GE(step, -kStepTolerance * brightest) << "sphere " << i << " goes the wrong way; windows:" << row;
    }
    const float change = increasing ? means.back() - means.front() : means.front() - means.back();
    EXPECT_GE(change, kMinChange * brightest) << "the row barely changes; windows:" << row;
  }
  EXPECT_GE(sweeps, 10);
}

}  // namespace
}  // namespace raylab::test
