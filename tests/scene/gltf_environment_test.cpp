// The environment image: reading it (root extras.raylab.environment, --env and --env-strength over it), every
// way a bad one is refused, and the importance-sampling tables (a density that integrates to 1 over the sphere
// and is positive wherever the image's bilinear radiance is).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "gltf_test_support.h"
#include "image/image.h"
#include "support/hostile_exr.h"
#include "scene/environment.h"
#include "scene/environment_tables.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A width x height EXR whose texel (x, y) is `value(x, y)`.
void writeEnvironment(const fs::path& path, std::uint32_t width, std::uint32_t height,
                      glm::vec3 (*value)(std::uint32_t, std::uint32_t)) {
  Image image(width, height);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) image.set(x, y, glm::vec4(value(x, y), 1.0f));
  }
  writeExrUnchecked(path.string(), image);  // some are NaN, which raylab's own writer refuses
}

glm::vec3 gradient(std::uint32_t x, std::uint32_t y) { return {0.1f * float(x), 1.0f, 0.2f * float(y)}; }

// A quad scene in `dir` whose root extras.raylab is `raylab`.
fs::path writeScene(const fs::path& dir, const json& raylab) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  if (!raylab.is_null()) b.doc()["extras"]["raylab"] = raylab;
  const fs::path path = dir / "scene.gltf";
  std::ofstream(path) << b.text();
  return path;
}

TEST(GltfEnvironment, TheFileNamesItsImageAndStrengthAndTheCommandLineReplacesThem) {
  const fs::path dir = freshDir("environment", "names");
  writeEnvironment(dir / "sky.exr", 8, 4, gradient);
  writeEnvironment(dir / "other.exr", 4, 2, gradient);
  const fs::path path = writeScene(dir, {{"environment", {{"uri", "sky.exr"}, {"strength", 2.5}, {"rotation", 90.0}}}});
  const Scene scene = loadGltfFile(path.string(), {});
  ASSERT_TRUE(scene.environment.hasImage());
  EXPECT_EQ(scene.environment.width, 8u);
  EXPECT_EQ(scene.environment.height, 4u);
  EXPECT_EQ(scene.environment.strength, 2.5f);
  EXPECT_FLOAT_EQ(scene.environment.rotation, 3.14159265f / 2.0f);
  EXPECT_EQ(scene.environment.texels[1 * 8 + 3], glm::vec3(0.3f, 1.0f, 0.2f));
  EXPECT_TRUE(scene.lights.empty()) << "an environment lights the scene: no default light";

  GltfOptions options;
  options.environment = (dir / "other.exr").string();
  options.environmentStrength = 0.5f;
  const Scene replaced = loadGltfFile(path.string(), options);
  EXPECT_EQ(replaced.environment.width, 4u);
  EXPECT_EQ(replaced.environment.strength, 0.5f);
}

TEST(GltfEnvironment, BadEnvironmentsAreRefusedNamingTheFieldOrFile) {
  const fs::path dir = freshDir("environment", "bad");
  const fs::path inner = dir / "inner";
  fs::create_directories(inner);
  writeEnvironment(inner / "sky.exr", 8, 4, gradient);
  writeEnvironment(inner / "nan.exr", 8, 4, [](std::uint32_t x, std::uint32_t y) {
    return x == 5 && y == 2 ? glm::vec3(NAN, 0.0f, 0.0f) : glm::vec3(1.0f);
  });
  writeEnvironment(inner / "inf.exr", 8, 4, [](std::uint32_t x, std::uint32_t) {
    return x == 1 ? glm::vec3(0.0f, INFINITY, 0.0f) : glm::vec3(1.0f);
  });
  writeEnvironment(inner / "huge.exr", 4, 2, [](std::uint32_t, std::uint32_t) { return glm::vec3(1e30f); });
  std::ofstream(inner / "text.exr") << "not an image";
  writeEnvironment(dir / "outside.exr", 8, 4, gradient);
  struct Case {
    json raylab;
    std::string mentions;
  };
  const Case cases[] = {
      {{{"environment", {{"uri", "missing.exr"}}}}, "missing.exr: no such file"},
      {{{"environment", {{"uri", "text.exr"}}}}, "text.exr: not a readable OpenEXR file"},
      {{{"environment", {{"uri", "nan.exr"}}}}, "texel (5, 2) is (nan"},
      {{{"environment", {{"uri", "inf.exr"}}}}, "texel (1, 0)"},
      {{{"environment", {{"uri", "huge.exr"}}}}, "at most 1e20"},
      {{{"environment", {{"uri", "sky.exr"}, {"strength", -1.0}}}},
       "environment.strength: expected a finite number >= 0"},
      {{{"environment", {{"uri", "sky.exr"}, {"strength", 1e39}}}}, "environment.strength"},
      {{{"environment", {{"uri", "sky.exr"}, {"strength", "2"}}}}, "environment.strength: expected a number"},
      {{{"environment", {{"uri", 3}}}}, "environment.uri: expected a string"},
      {{{"environment", {{"strength", 1.0}}}}, "environment: has no uri"},
      {{{"environment", {{"uri", "sky.exr"}, {"turn", 1.0}}}}, "unknown key 'turn'"},
      {{{"environment", {{"uri", "sky.exr"}, {"rotation", 400.0}}}}, "environment.rotation: expected degrees"},
      {{{"environment", "sky.exr"}}, "extras.raylab.environment: expected {"},
      {{{"background", {1, 1, 1}}}, "unknown key 'background'"},
      {{{"environment", {{"uri", "data:image/x-exr;base64,AAAA"}}}}, "has a scheme"},
      {{{"environment", {{"uri", "../outside.exr"}}}}, "outside the scene's directory"},
  };
  for (const Case& c : cases) {
    const fs::path path = writeScene(inner, c.raylab);
    const std::string error = errorOf([&] { loadGltfFile(path.string(), {}); });
    EXPECT_NE(error.find(c.mentions), std::string::npos) << c.raylab.dump() << " gave: " << error;
    EXPECT_EQ(error.rfind(path.string(), 0), 0u) << "the message starts with the file: " << error;
  }
  // The command line's own options are named as such.
  const fs::path plain = writeScene(inner, nullptr);
  GltfOptions missing;
  missing.environment = (dir / "nope.exr").string();
  EXPECT_NE(errorOf([&] { loadGltfFile(plain.string(), missing); }).find("--env: environment image"), std::string::npos);
  GltfOptions strengthAlone;
  strengthAlone.environmentStrength = 2.0f;
  EXPECT_NE(errorOf([&] { loadGltfFile(plain.string(), strengthAlone); }).find("--env-strength: the scene has no "),
            std::string::npos);
  GltfOptions negative;
  negative.environment = (inner / "sky.exr").string();
  negative.environmentStrength = -2.0f;
  EXPECT_NE(errorOf([&] { loadGltfFile(plain.string(), negative); }).find("--env-strength"), std::string::npos);
}

// The density of environmentLightSample, integrated over the sphere by the midpoint rule on a fine (u, v) grid, is 1;
// and it is positive wherever the bilinear radiance is, so light sampling alone misses nothing.
TEST(EnvironmentTables, TheSamplingDensityIntegratesToOneAndCoversEveryLitDirection) {
  Environment environment;
  environment.width = 16;
  environment.height = 8;
  environment.texels.assign(16 * 8, glm::vec3(0.0f));
  environment.texels[3 * 16 + 5] = glm::vec3(100.0f, 50.0f, 10.0f);  // a sun
  environment.texels[0 * 16 + 15] = glm::vec3(0.0f, 0.0f, 1.0f);     // blue at the seam and the pole
  environment.texels[7 * 16 + 0] = glm::vec3(0.5f);
  const EnvironmentTables tables = buildEnvironmentTables(environment);
  EXPECT_EQ(tables.marginalCdf.back(), 1.0f);
  constexpr int kU = 1024, kV = 512;
  double integral = 0.0;
  int uncovered = 0;
  for (int j = 0; j < kV; ++j) {
    for (int i = 0; i < kU; ++i) {
      const glm::vec2 uv((i + 0.5f) / kU, (j + 0.5f) / kV);
      const glm::vec3 d = environmentDirection(uv);
      const double pdf = environmentPdf(tables, d);
      const double sinTheta = std::sin(3.14159265358979 * uv.y);
      integral += pdf * sinTheta * (2.0 * 3.14159265358979 / kU) * (3.14159265358979 / kV);
      const glm::vec3 radiance = environmentLookup(environment, d);
      if (std::max({radiance.r, radiance.g, radiance.b}) > 0.0f && !(pdf > 0.0)) ++uncovered;
    }
  }
  EXPECT_NEAR(integral, 1.0, 1e-3);
  EXPECT_EQ(uncovered, 0);
  // The sun's texel is where the density peaks.
  EXPECT_EQ(std::max_element(tables.f.begin(), tables.f.end()) - tables.f.begin(), 3 * 16 + 5);
}

}  // namespace
}  // namespace raylab::test
