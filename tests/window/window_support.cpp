#include "window/window_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/camera_frame.h"

namespace raylab::test {

namespace fs = std::filesystem;

std::string scratchDir() {
  const fs::path dir = fs::temp_directory_path() / "raylab_window_test";
  fs::create_directories(dir);
  return dir.string();
}

std::string findXvfbRun() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir) / "xvfb-run";
    if (fs::exists(candidate)) return candidate.string();
  }
  return "";
}

CommandResult runView(const std::vector<std::string>& arguments, const std::vector<std::string>& environment) {
  const std::string xvfbRun = findXvfbRun();
  if (xvfbRun.empty()) {
    ADD_FAILURE() << "xvfb-run is not installed: run tools/setup.sh test (it installs the packages xvfb and xauth)";
    return {};
  }
  std::vector<std::string> command = {xvfbRun, "-a", "-s", "-screen 0 1024x768x24", RAYLAB_BINARY, "view"};
  command.insert(command.end(), arguments.begin(), arguments.end());
  return runCommand(command, environment);
}

std::string writeScript(const std::string& name, const std::string& text) {
  const std::string path = scratchDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

void expectCleanRun(const CommandResult& result) {
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_EQ(result.output.find("[validation"), std::string::npos) << result.output;
}

void expectSameImage(const Image& actual, const Image& expected, const std::string& what) {
  ASSERT_EQ(actual.width, expected.width) << what;
  ASSERT_EQ(actual.height, expected.height) << what;
  std::size_t worst = 0;
  double worstError = 0.0;
  for (std::size_t i = 0; i < actual.rgba.size(); ++i) {
    const double expectedValue = expected.rgba[i];
    const double error = std::abs(actual.rgba[i] - expectedValue) / (1e-3 + std::abs(expectedValue));
    if (error > worstError) {
      worstError = error;
      worst = i;
    }
  }
  EXPECT_LT(worstError, 1e-5) << what << ": float " << worst << " is " << actual.rgba[worst] << ", expected "
                              << expected.rgba[worst];
}

double meanLuminance(const Image& image) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
  return sum / (3.0 * image.width * image.height);
}

Image renderReference(const std::vector<std::string>& extra, const std::string& exrPath) {
  std::vector<std::string> args = {"render", "--out", exrPath, "--png", exrPath + ".png"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CommandResult result = runRaylab(args);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return readExr(exrPath);
}

std::vector<bool> sphereMask(const Scene& scene, const std::string& materialName, std::uint32_t width,
                             std::uint32_t height, float radiusScale) {
  std::uint32_t material = UINT32_MAX;
  for (std::uint32_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == materialName) material = i;
  }
  const Sphere* sphere = nullptr;
  for (const Sphere& s : scene.spheres) {
    if (s.material == material) sphere = &s;
  }
  if (sphere == nullptr) {
    ADD_FAILURE() << "the scene has no sphere of material '" << materialName << "'";
    return std::vector<bool>(std::size_t(width) * height, false);
  }
  gpu::FrameParams params{};
  applyCamera(params, scene.camera, width, height);
  const float radius = sphere->radius * radiusScale;
  std::vector<bool> mask(std::size_t(width) * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::vec2 ndc(2.0f * (x + 0.5f) / width - 1.0f, 1.0f - 2.0f * (y + 0.5f) / height);
      const glm::vec3 d = glm::normalize(params.cameraForward + ndc.x * params.cameraRight + ndc.y * params.cameraUp);
      const glm::vec3 oc = params.cameraOrigin - sphere->center;
      const float b = glm::dot(oc, d);
      const float c = glm::dot(oc, oc) - radius * radius;
      mask[std::size_t(y) * width + x] = b * b - c >= 0.0f && -b > 0.0f;
    }
  }
  return mask;
}

}  // namespace raylab::test
