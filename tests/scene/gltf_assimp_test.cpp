// Real glTF files from Debian's assimp-testmodels: the good ones load with sane contents, the broken ones
// give a raylab::Error naming the file and the problem, or the documented repair (docs/scenes.md).
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_support.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

class GltfAssimp : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::is_directory(assimpDirectory()))
        << assimpDirectory() << " is missing: install the assimp-testmodels package (run tools/setup.sh test)";
  }

  static std::string path(const std::string& relative) { return (assimpDirectory() / relative).string(); }

  // The error message for `relative`, after checking that it names the file.
  static std::string errorFor(const std::string& relative) {
    WarningCapture warnings;
    const std::string error = errorOf([&] { loadGltfFile(path(relative), {}); });
    EXPECT_EQ(error.rfind(path(relative) + ": ", 0), 0u) << "the message starts with the file: " << error;
    return error;
  }
};

std::size_t triangles(const Scene& scene) {
  std::size_t count = 0;
  for (const MeshInstance& instance : scene.instances) count += scene.meshes[instance.mesh].indices.size() / 3;
  return count;
}

TEST_F(GltfAssimp, BoxTexturedLoadsInEveryPackaging) {
  for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                           "BoxTextured-glTF-Embedded/BoxTextured.gltf",
                           "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf"}) {
    SCOPED_TRACE(file);
    WarningCapture warnings;
    const Scene scene = loadGltfFile(path(file), {});
    EXPECT_EQ(scene.name, "BoxTextured");
    EXPECT_EQ(triangles(scene), 12u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].width, 211u);
    EXPECT_EQ(scene.textures[0].rgba.size(), 211u * 211u * 4u);
    ASSERT_EQ(scene.materials.size(), 1u);
    ASSERT_EQ(scene.materials[0].record.textures, 0);
    EXPECT_EQ(scene.materialTextures[0].refs[gpu::kTextureBaseColor].texture, 0);
    EXPECT_FALSE(scene.meshes[0].uvs.empty());
    // No camera and no lights in the file: the documented defaults, each announced once.
    EXPECT_EQ(scene.camera.name, "default");
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(warnings.count("has no perspective camera"), 1);
    EXPECT_EQ(warnings.count("has no KHR_lights_punctual lights"), 1);
  }
}

TEST_F(GltfAssimp, TwoCylinderEngineLoadsWithItsCamera) {
  WarningCapture warnings;
  const Scene scene = loadGltfFile(path("2CylinderEngine-glTF-Binary/2CylinderEngine.glb"), {});
  EXPECT_EQ(scene.meshes.size(), 34u) << "one raylab mesh per glTF primitive";
  EXPECT_GT(scene.instances.size(), 100u);
  EXPECT_GT(triangles(scene), 100000u);
  EXPECT_NEAR(scene.camera.yfov, 0.3143f, 1e-4f) << "the file's own camera";
  EXPECT_EQ(scene.lights.size(), 1u);
}

TEST_F(GltfAssimp, BoxWithInfinitesIsAnErrorNamingTheAccessor) {
  const std::string error = errorFor("BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb");
  EXPECT_NE(error.find("(POSITION of mesh 0 'Mesh' primitive 0): position 0 is not finite (-inf, -0.5, 0.5)"),
            std::string::npos) << error;
}

TEST_F(GltfAssimp, BoxBadNormalsIsRepaired) {
  WarningCapture warnings;
  const Scene scene = loadGltfFile(path("BoxBadNormals-glTF-Binary/BoxBadNormals.glb"), {});
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].normals.size(), 24u);
  for (const glm::vec3& n : scene.meshes[0].normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  EXPECT_EQ(warnings.count("repaired 4 zero or non-finite normals"), 1);
  EXPECT_EQ(warnings.count("4 non-unit normals (normalised)"), 1);
  // The first face's normals were zero; they now match the face, whose normal is +z.
  EXPECT_NEAR(scene.meshes[0].normals[0].z, 1.0f, 1e-5f);
}

TEST_F(GltfAssimp, IndexOutOfRangeIsAnError) {
  EXPECT_NE(errorFor("IndexOutOfRange/IndexOutOfRange.gltf")
                .find("(indices of mesh 0 'Mesh' primitive 0): index 255 at position 0 is out of range (24 vertices)"),
            std::string::npos);
  EXPECT_NE(errorFor("IndexOutOfRange/AllIndicesOutOfRange.gltf").find("index 65535 at position 0 is out of range"),
            std::string::npos);
}

TEST_F(GltfAssimp, MissingBinIsAnErrorNamingTheBuffer) {
  const std::string error = errorFor("MissingBin/BoxTextured.gltf");
  EXPECT_NE(error.find("BoxTextured0.bin: no such file"), std::string::npos) << error;
}

TEST_F(GltfAssimp, WrongTypesAreErrorsNamingTheProperty) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"wrongTypes/badArray.gltf", "meshes[0].primitives: expected an array, found an object"},
      {"wrongTypes/badExtension.gltf",
       "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform: expected an object, "
       "found the string \"Not an object\""},
      {"wrongTypes/badNumber.gltf", "materials[0].normalTexture: the required property 'index' is missing"},
      {"wrongTypes/badObject.gltf", "materials[0].pbrMetallicRoughness: expected an object, found an array"},
      {"wrongTypes/badString.gltf", "scenes[0].name: expected a string, found 42"},
      {"wrongTypes/badUint.gltf",
       "materials[0].pbrMetallicRoughness.baseColorTexture.index: expected a non-negative integer, found -1"},
  };
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(assimpDirectory() / "wrongTypes")) {
    if (entry.path().extension() == ".gltf") ++files;
  }
  EXPECT_EQ(files, cases.size()) << "every file under wrongTypes/ is covered";
  for (const auto& [file, expected] : cases) {
    const std::string error = errorFor(file);
    EXPECT_NE(error.find(expected), std::string::npos) << error;
  }
}

TEST_F(GltfAssimp, SchemaFailuresAndBrokenStructureAreErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"SchemaFailures/sceneWrongType.gltf", "scene: expected a non-negative integer, found the string \"hello\""},
      {"RecursiveNodes/RecursiveNodes.gltf", "node 0: is its own ancestor (the node hierarchy has a cycle)"},
      {"TestNoRootNode/NoScene.gltf", "has no scenes and no nodes: nothing to render"},
      {"TestNoRootNode/SceneWithoutNodes.gltf", "the scene has nothing to render"},
      {"IncorrectVertexArrays/Cube.gltf", "mesh 1 'TruncatedCube' primitive 0: a triangle list of 35 vertices"},
      {"draco/2CylinderEngine.gltf", "requires the extension KHR_draco_mesh_compression"},
      {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "requires the extension KHR_technique_webgl"},
  };
  for (const auto& [file, expected] : cases) {
    const std::string error = errorFor(file);
    EXPECT_NE(error.find(expected), std::string::npos) << error;
  }
}

TEST_F(GltfAssimp, OrthographicCamerasAreSkipped) {
  WarningCapture warnings;
  const Scene scene = loadGltfFile(path("cameras/Cameras.gltf"), {});
  EXPECT_NEAR(scene.camera.yfov, 0.7f, 1e-6f);
  EXPECT_EQ(warnings.count("orthographic cameras"), 1);
}

}  // namespace
}  // namespace raylab::test
