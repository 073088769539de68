// The committed scenes (assets/scenes): each loads without a warning, with the spheres, lights and camera
// it was written with, and every sweep's materials go monotonically in the swept parameter along the row.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>

#include "gltf_test_support.h"
#include "brdf_params/material_params.h"

namespace raylab::test {
namespace {

struct Expected {
  std::size_t spheres;
  std::size_t lights;
  std::size_t instances;
};

// What tools/scenes/make_scenes.py writes; a new scene must be added here.
const std::map<std::string, Expected> kExpected = {
    {"cornell_box", {2, 1, 5}},
    {"cornell_box_area", {2, 0, 6}},  // lit by its emissive quad only: no default light
    {"glossy_room", {1, 0, 14}},      // likewise: a lamp quad in a tray of eight, the room's five walls
    {"minimal", {1, 1, 1}},
    {"showcase", {10, 3, 2}},
    {"showcase_hdri", {10, 0, 2}},  // lit by its environment image only: no default light
    {"showcase_modern", {21, 0, 2}},  // likewise
    {"showcase_layered", {12, 0, 2}},  // likewise
    {"sweep_ashikhmin_shirley_nv", {8, 1, 0}},
    {"sweep_blinnphong_s", {8, 1, 0}},
    {"sweep_cooktorrance_eta", {8, 1, 0}},
    {"sweep_cooktorrance_m", {8, 1, 0}},
    {"sweep_eon_r", {8, 1, 0}},
    {"sweep_ggx_conductor_alpha_x", {8, 1, 0}},
    {"sweep_ggx_conductor_multiscatter", {8, 1, 0}},
    {"sweep_ggx_dielectric_alpha_x", {8, 1, 2}},
    {"sweep_glass_eta", {8, 1, 2}},
    {"sweep_gltf_pbr_roughness", {8, 1, 0}},
    {"sweep_lambert_delta", {8, 1, 2}},
    {"sweep_lambert_rho_d", {8, 1, 0}},
    {"sweep_oren_nayar_sigma", {8, 1, 0}},
    {"sweep_phong_rho_s", {8, 1, 0}},
    {"sweep_phong_s", {8, 1, 0}},
    {"sweep_lafortune_rho_s2", {8, 1, 0}},
    {"sweep_ward_alpha_y", {8, 1, 0}},
};

nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

TEST(GltfAssets, EveryCommittedSceneLoadsCleanlyWithItsContents) {
  const std::vector<std::filesystem::path> files = assetFiles();
  ASSERT_FALSE(files.empty()) << "no scenes in " << assetsDirectory() << ": run tools/scenes/make_scenes.py";
  for (const std::filesystem::path& file : files) {
    SCOPED_TRACE(file.string());
    const auto expected = kExpected.find(file.stem().string());
    ASSERT_NE(expected, kExpected.end()) << "a scene this test does not know: add it to kExpected";
    WarningCapture warnings;
    const Scene scene = loadGltfFile(file.string(), {});
    EXPECT_TRUE(warnings.messages().empty()) << warnings.messages().front();
    EXPECT_EQ(scene.spheres.size(), expected->second.spheres);
    EXPECT_EQ(scene.lights.size(), expected->second.lights);
    EXPECT_EQ(scene.instances.size(), expected->second.instances);
    EXPECT_EQ(scene.camera.name, "camera") << "every committed scene has its own camera";
  }
  for (const auto& [name, expected] : kExpected) {
    EXPECT_TRUE(std::filesystem::exists(assetsDirectory() / (name + ".gltf"))) << name << ".gltf is missing";
  }
}

TEST(GltfAssets, SweepMaterialsGoMonotonicallyAlongTheRow) {
  int sweeps = 0;
  for (const std::filesystem::path& file : assetFiles()) {
    const nlohmann::json doc = readJson(file);
    const nlohmann::json* sweep = nullptr;
    if (doc["scenes"][0].contains("extras") && doc["scenes"][0]["extras"].contains("sweep")) {
      sweep = &doc["scenes"][0]["extras"]["sweep"];
    }
    if (file.stem().string().rfind("sweep_", 0) == 0) {
      ASSERT_NE(sweep, nullptr) << file << " has no extras.sweep";
    }
    if (sweep == nullptr) continue;
    SCOPED_TRACE(file.string());
    ++sweeps;
    const std::string parameter = (*sweep)["parameter"];
    const std::string trend = (*sweep)["trend"];
    EXPECT_TRUE(trend == "increasing" || trend == "decreasing" || trend == "steady") << trend;
    WarningCapture warnings;
    Scene scene = loadGltfFile(file.string(), {});
    std::sort(scene.spheres.begin(), scene.spheres.end(),
              [](const Sphere& a, const Sphere& b) { return a.center.x < b.center.x; });
    const ModelInfo* model = findModel((*sweep)["model"].get<std::string>());
    ASSERT_NE(model, nullptr);
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
      const gpu::MaterialRecord& record = scene.materials[scene.spheres[i].material].record;
      EXPECT_EQ(record.model, model->id) << "sphere " << i;
      EXPECT_NEAR(getParam(record, parameter).x, (*sweep)["values"][i].get<float>(), 1e-4f) << "sphere " << i;
      if (i > 0) {
        const gpu::MaterialRecord& previous = scene.materials[scene.spheres[i - 1].material].record;
        EXPECT_GT(getParam(record, parameter).x, getParam(previous, parameter).x) << "sphere " << i;
      }
    }
  }
  EXPECT_GE(sweeps, 10);
}

// docs/scenes.md prints minimal.gltf compactly; both must say the same (the generator aside).
TEST(GltfAssets, TheDocumentedExampleIsTheCommittedMinimalScene) {
  std::ifstream docs(std::filesystem::path(RAYLAB_SOURCE_DIR) / "docs" / "scenes.md");
  ASSERT_TRUE(docs) << "docs/scenes.md is missing";
  const std::string text((std::istreambuf_iterator<char>(docs)), std::istreambuf_iterator<char>());
  const std::size_t section = text.find("## A minimal file");
  ASSERT_NE(section, std::string::npos);
  const std::size_t begin = text.find("```json\n", section);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = text.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  nlohmann::json documented = nlohmann::json::parse(text.substr(begin + 8, end - begin - 8));
  nlohmann::json committed = readJson(assetsDirectory() / "minimal.gltf");
  documented["asset"].erase("generator");
  committed["asset"].erase("generator");
  EXPECT_EQ(documented, committed) << "regenerate the example in docs/scenes.md from assets/scenes/minimal.gltf";
  const Scene scene = loadGltfText(text.substr(begin + 8, end - begin - 8), "", "docs example", {});
  EXPECT_EQ(scene.spheres.size(), 1u);
}

}  // namespace
}  // namespace raylab::test
