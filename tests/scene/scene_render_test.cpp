// Renders of the committed scenes and of real glTF files: no NaN or Inf pixel, something lit, and along
// every sweep's row the trend of the statistic that the scene's extras.sweep states
// (tools/scenes/make_scenes.py says why each holds). With RAYLAB_TEST_IMAGES=DIR set, every render is also
// written to DIR as a PNG.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
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

// The sweeps are measured on the row as the asset's camera "row" frames it: one square cell of kSweepCell
// pixels per sphere. The statistics (tools/scenes/make_scenes.py) are taken over each sphere's projected disc, less
// its anti-aliased rim.
constexpr const char* kSweepCamera = "row";
constexpr std::uint32_t kSweepCell = 64;
constexpr std::uint32_t kSweepSpp = 16;
constexpr float kDiscFraction = 0.9f;
constexpr std::size_t kMinDiscPixels = 500;
// Tolerances relative to the row's largest statistic: a step may go the wrong way by this much (sampling
// noise of the jittered pixels), and the row must change by at least kMinChange end to end. A highlight's
// area is a whole number of pixels, and with the jitter's noise its rim pixels come and go: small
// highlights may also step back by kAreaTolerancePixels.
constexpr float kStepTolerance = 0.01f;
constexpr float kAreaTolerancePixels = 2.0f;
constexpr float kMinChange = 0.2f;
// A "steady" row (a parameter that changes the look but not the statistic, like EON's roughness, which keeps the
// energy): every sphere within this fraction of the row's mean.
constexpr float kSteadyTolerance = 0.02f;

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

Scene loadQuietly(const fs::path& path, const std::string& camera = "") {
  WarningCapture warnings;  // the loader tests check the warnings; here they would only clutter the log
  return loadGltfFile(path.string(), {camera});
}

// Both integrators, and (renderImage) both backends bit for bit alike. A sweep scene is made for the slides'
// integrator (its path render would add only a kernel variant to compile: the showcases path-trace every model), and
// SweepsShowTheirStatedTrendAlongTheRow renders it with that integrator, checks the same (finite, not black, both
// backends alike) and more: rendering it here too cost each of the 17 sweeps a second renderer on each backend.
TEST_F(SceneRenderTest, EveryCommittedSceneRendersFiniteWithBothIntegrators) {
  const std::vector<fs::path> files = assetFiles();
  ASSERT_FALSE(files.empty()) << "no scenes in " << assetsDirectory() << ": run tools/scenes/make_scenes.py";
  for (const fs::path& file : files) {
    if (file.stem().string().rfind("sweep_", 0) == 0) continue;
    const Scene scene = loadQuietly(file);
    for (IntegratorChoice integrator : {IntegratorChoice::kSlides, IntegratorChoice::kPath}) {
      const std::string name = file.stem().string() + "_" + std::string(integratorName(chooseIntegrator(scene, integrator)));
      SCOPED_TRACE(name);
      RenderSettings settings;
      settings.width = 64;
      settings.height = 48;
      KernelFeatures kernel = featuresOf(scene);
      kernel.integrator = chooseIntegrator(scene, integrator);
      settings.kernel = kernel;
      const Image image = renderImage(device(), scene, settings, 2);
      saveForInspection(image, name);
      expectSaneImage(image, name);
    }
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

// BoxTextured's binary (.glb) and embedded (data URI) encodings hold the same asset: the same image bit for bit.
// Its .gltf variant differs only by its sampler's wrap modes: mirrored repeat along u, whose faces' UVs run over
// [k, k + 1], so the faces of odd k show the logo mirrored; with its wrap modes set to the others' repeat, it too
// renders bit for bit alike.
TEST_F(SceneRenderTest, BoxTexturedsEncodingsRenderTheSameImage) {
  ASSERT_TRUE(fs::is_directory(assimpDirectory()))
      << assimpDirectory() << " is missing: install the assimp-testmodels package (run tools/setup.sh test)";
  const auto boxImage = [&](const Scene& scene) { return render(device(), scene, 96, 72, 4); };
  const Image binary = boxImage(loadQuietly(assimpDirectory() / "BoxTextured-glTF-Binary/BoxTextured.glb"));
  const Image embedded = boxImage(loadQuietly(assimpDirectory() / "BoxTextured-glTF-Embedded/BoxTextured.gltf"));
  Scene separate = loadQuietly(assimpDirectory() / "BoxTextured-glTF/BoxTextured.gltf");
  ASSERT_EQ(separate.textures.size(), 1u);
  EXPECT_EQ(separate.textures[0].wrapS, gpu::kWrapMirror);
  EXPECT_EQ(separate.textures[0].wrapT, gpu::kWrapClamp);
  const Image mirrored = boxImage(separate);
  separate.textures[0].wrapS = separate.textures[0].wrapT = gpu::kWrapRepeat;
  const Image repeated = boxImage(separate);

  EXPECT_TRUE(binary.rgba == embedded.rgba) << "the binary and the embedded encoding render alike";
  EXPECT_TRUE(binary.rgba == repeated.rgba) << "with the same wrap modes, the .gltf variant renders alike too";
  std::size_t differing = 0, box = 0;
  for (std::uint32_t y = 0; y < binary.height; ++y) {
    for (std::uint32_t x = 0; x < binary.width; ++x) {
      differing += binary.at(x, y) != mirrored.at(x, y);
      box += binary.at(x, y) != glm::vec4(0.0f, 0.0f, 0.0f, binary.at(x, y).a);
    }
  }
  EXPECT_GT(box, 1000u);
  EXPECT_GT(differing, box / 10) << "the mirrored faces show";
}

// TextureTransformTest (Khronos) renders as its KHR_texture_transforms baked into the meshes' UVs say it must:
// the transform is affine, so transforming each vertex's UVs on the host and dropping the transform gives the same
// image up to float rounding (a few pixels on texel edges); and it is not the image without the transforms.
TEST_F(SceneRenderTest, TextureTransformTestEqualsItsTransformsBakedIntoTheUvs) {
  ASSERT_TRUE(fs::is_directory(assimpDirectory()))
      << assimpDirectory() << " is missing: install the assimp-testmodels package (run tools/setup.sh test)";
  const Scene scene = loadQuietly(assimpDirectory() / "textureTransform/TextureTransformTest.gltf");
  Scene baked = scene, ignored = scene;
  int transformed = 0;
  for (const MeshInstance& instance : scene.instances) {
    const int textures = scene.materials[instance.material].record.textures;
    if (textures < 0) continue;
    const gpu::TextureRef& ref = scene.materialTextures[std::size_t(textures)].refs[gpu::kTextureBaseColor];
    if (ref.row0 == glm::vec3(1, 0, 0) && ref.row1 == glm::vec3(0, 1, 0) && ref.texCoord == 0) continue;
    Mesh& mesh = baked.meshes[instance.mesh];
    const std::vector<glm::vec2>& set = ref.texCoord == 1 ? scene.meshes[instance.mesh].uvs1 : scene.meshes[instance.mesh].uvs;
    ASSERT_EQ(set.size(), mesh.positions.size());
    for (std::size_t v = 0; v < set.size(); ++v) {
      const glm::vec3 uv(set[v], 1.0f);
      mesh.uvs[v] = glm::vec2(glm::dot(ref.row0, uv), glm::dot(ref.row1, uv));
    }
    for (Scene* s : {&baked, &ignored}) s->materialTextures[std::size_t(textures)].refs[gpu::kTextureBaseColor] = textureRef(ref.texture);
    ++transformed;
  }
  EXPECT_EQ(transformed, 6) << "offset U, V and UV, rotation, scale, all";
  const Image a = render(device(), scene, 160, 120, 1);
  const Image b = render(device(), baked, 160, 120, 1);
  const Image c = render(device(), ignored, 160, 120, 1);
  std::size_t differBaked = 0, differIgnored = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    const float dB = std::max({std::abs(a.rgba[i] - b.rgba[i]), std::abs(a.rgba[i + 1] - b.rgba[i + 1]),
                               std::abs(a.rgba[i + 2] - b.rgba[i + 2])});
    const float dC = std::max({std::abs(a.rgba[i] - c.rgba[i]), std::abs(a.rgba[i + 1] - c.rgba[i + 1]),
                               std::abs(a.rgba[i + 2] - c.rgba[i + 2])});
    differBaked += dB > 1e-3f;
    differIgnored += dC > 1e-3f;
  }
  const std::size_t pixels = a.rgba.size() / 4;
  EXPECT_LT(differBaked, pixels / 200) << "baked UVs render alike, but for texel edges";
  EXPECT_GT(differIgnored, pixels / 50) << "without the transforms the squares show other texels";
}

// The luminance-like (r + g + b) / 3 of the pixels whose centres lie within kDiscFraction of a sphere's
// projected radius from its projected centre, projecting as applyCamera sets the kernel's camera up.
std::vector<float> discPixels(const Image& image, const Scene& scene, const Sphere& sphere) {
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
  const float discRadius = kDiscFraction * radiusPixels;

  std::vector<float> pixels;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const float dx = float(x) + 0.5f - centerX;
      const float dy = float(y) + 0.5f - centerY;
      if (dx * dx + dy * dy > discRadius * discRadius) continue;
      const glm::vec4 pixel = image.at(x, y);
      pixels.push_back((pixel.r + pixel.g + pixel.b) / 3.0f);
    }
  }
  return pixels;
}

// The statistics extras.sweep may name (tools/scenes/make_scenes.py says what each measures).
float sweepStatistic(const std::string& statistic, const std::vector<float>& disc) {
  if (statistic == "mean") {
    double sum = 0.0;
    for (float value : disc) sum += value;
    return float(sum / double(disc.size()));
  }
  if (statistic == "highlight_area") {
    const float brightest = *std::max_element(disc.begin(), disc.end());
    return float(std::count_if(disc.begin(), disc.end(), [&](float value) { return value > 0.5f * brightest; }));
  }
  ADD_FAILURE() << "unknown statistic '" << statistic << "' in extras.sweep";
  return 0.0f;
}

TEST_F(SceneRenderTest, SweepsShowTheirStatedTrendAlongTheRow) {
  int sweeps = 0;
  for (const fs::path& file : assetFiles()) {
    std::ifstream in(file);
    const nlohmann::json doc = nlohmann::json::parse(in);
    const nlohmann::json& extras = doc["scenes"][0].value("extras", nlohmann::json::object());
    const bool named = file.stem().string().rfind("sweep_", 0) == 0;
    EXPECT_EQ(extras.contains("sweep"), named) << file << ": a sweep scene is named sweep_* and carries extras.sweep";
    if (!extras.contains("sweep")) continue;
    ++sweeps;
    const std::string name = file.stem().string();
    const nlohmann::json& sweep = extras["sweep"];
    ASSERT_TRUE(sweep.contains("statistic") && sweep.contains("trend") && sweep.contains("why"))
        << name << ": extras.sweep must state a statistic, its trend and why (tools/scenes/make_scenes.py)";
    const std::string statistic = sweep["statistic"].get<std::string>();
    const std::string trend = sweep["trend"].get<std::string>();
    ASSERT_TRUE(trend == "increasing" || trend == "decreasing" || trend == "steady") << name << ": trend '" << trend << "'";
    const bool increasing = trend == "increasing";
    SCOPED_TRACE(name + " (" + statistic + " " + trend + ": " + sweep["why"].get<std::string>() + ")");

    Scene scene = loadQuietly(file, kSweepCamera);
    std::sort(scene.spheres.begin(), scene.spheres.end(),
              [](const Sphere& a, const Sphere& b) { return a.center.x < b.center.x; });
    ASSERT_EQ(scene.spheres.size(), sweep["values"].size()) << "one sphere per value";
    const auto cells = std::uint32_t(scene.spheres.size());
    const Image image = render(device(), scene, cells * kSweepCell, kSweepCell, kSweepSpp);
    saveForInspection(image, name + "_sweep");
    expectSaneImage(image, name);

    std::vector<float> values;
    std::string row;
    for (const Sphere& sphere : scene.spheres) {
      const std::vector<float> disc = discPixels(image, scene, sphere);
      ASSERT_GE(disc.size(), kMinDiscPixels) << "the sphere is too small to measure";
      values.push_back(sweepStatistic(statistic, disc));
      char shown[32];
      std::snprintf(shown, sizeof shown, " %.4g", values.back());
      row += shown;
    }
    const float largest = *std::max_element(values.begin(), values.end());
    ASSERT_GT(largest, 0.0f) << "the statistic is 0 for every sphere:" << row;
    if (trend == "steady") {
      // The parameter changes the look, not the statistic: every sphere within kSteadyTolerance of the row's mean.
      const float mean = std::accumulate(values.begin(), values.end(), 0.0f) / float(values.size());
      for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_NEAR(values[i], mean, kSteadyTolerance * mean) << "sphere " << i << " departs from the row; row:" << row;
      }
      continue;
    }
    const float tolerance =
        std::max(kStepTolerance * largest, statistic == "highlight_area" ? kAreaTolerancePixels : 0.0f);
    for (std::size_t i = 1; i < values.size(); ++i) {
      const float step = increasing ? values[i] - values[i - 1] : values[i - 1] - values[i];
      EXPECT_GE(step, -tolerance) << "sphere " << i << " goes the wrong way; row:" << row;
    }
    const float change = increasing ? values.back() - values.front() : values.front() - values.back();
    EXPECT_GE(change, kMinChange * largest) << "the row barely changes; row:" << row;
  }
  EXPECT_GE(sweeps, 10);
}

}  // namespace
}  // namespace raylab::test
