// glTF files as files: .gltf and .glb told apart by content, external buffers, and the errors for missing,
// malformed or unsupported files, each naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "gltf_test_support.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path directory = fs::path(::testing::TempDir()) / "raylab_gltf_file_test";
  fs::create_directories(directory);
  return directory / name;
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void appendU32(std::string& bytes, std::uint32_t value) {
  char raw[4];
  std::memcpy(raw, &value, 4);
  bytes.append(raw, 4);
}

// A GLB container holding `json` (and no BIN chunk: the builder's buffers are data URIs).
std::string glb(std::string json) {
  while (json.size() % 4 != 0) json += ' ';
  std::string bytes = "glTF";
  appendU32(bytes, 2);
  appendU32(bytes, static_cast<std::uint32_t>(12 + 8 + json.size()));
  appendU32(bytes, static_cast<std::uint32_t>(json.size()));
  appendU32(bytes, 0x4E4F534A);
  return bytes + json;
}

GltfBuilder quadScene() {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  return b;
}

TEST(GltfFile, TextAndBinaryFilesAreToldApartByContent) {
  const std::string text = quadScene().text();
  const fs::path gltf = scratch("quad.gltf");
  const fs::path binary = scratch("quad.glb");
  const fs::path binaryNamedGltf = scratch("binary_in_disguise.gltf");
  writeFile(gltf, text);
  writeFile(binary, glb(text));
  writeFile(binaryNamedGltf, glb(text));
  WarningCapture warnings;
  for (const fs::path& path : {gltf, binary, binaryNamedGltf}) {
    const Scene scene = loadGltfFile(path.string(), {});
    EXPECT_EQ(scene.name, path.stem().string()) << "Scene.name is the file's stem";
    EXPECT_EQ(scene.instances.size(), 1u) << path;
  }
  const fs::path textNamedGlb = scratch("text_in_disguise.glb");
  writeFile(textNamedGlb, text);
  const std::string error = errorOf([&] { loadGltfFile(textNamedGlb.string(), {}); });
  EXPECT_EQ(error, textNamedGlb.string() + ": a .glb file must start with the GLB magic 'glTF'");
}

TEST(GltfFile, ATruncatedGlbIsAnError) {
  const fs::path path = scratch("truncated.glb");
  writeFile(path, glb(quadScene().text()).substr(0, 40));
  const std::string error = errorOf([&] { loadGltfFile(path.string(), {}); });
  EXPECT_NE(error.find(path.string() + ": GLB header says"), std::string::npos) << error;
}

TEST(GltfFile, ExternalBuffersResolveNextToTheFile) {
  GltfBuilder b = quadScene();
  nlohmann::json doc = nlohmann::json::parse(b.text());
  const std::string uri = doc["buffers"][0]["uri"];
  // Decode the data URI the builder wrote back into bytes for a .bin file beside the .gltf.
  const Scene reference = loadGltfText(b.text(), "", "reference", {});
  std::string bin;
  for (const glm::vec3& p : reference.meshes[0].positions) bin.append(reinterpret_cast<const char*>(&p), 12);
  const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
  doc["buffers"][0] = {{"uri", "quad.bin"}, {"byteLength", bin.size()}};
  doc["bufferViews"][0]["byteOffset"] = 0;
  doc["bufferViews"][1]["byteOffset"] = 48;
  writeFile(scratch("quad.bin"), bin);
  writeFile(scratch("external.gltf"), doc.dump());
  WarningCapture warnings;
  EXPECT_EQ(loadGltfFile(scratch("external.gltf").string(), {}).meshes[0].positions, reference.meshes[0].positions);

  fs::remove(scratch("quad.bin"));
  const std::string error = errorOf([&] { loadGltfFile(scratch("external.gltf").string(), {}); });
  EXPECT_NE(error.find(scratch("external.gltf").string() + ": "), std::string::npos) << error;
  EXPECT_NE(error.find("quad.bin"), std::string::npos) << "the message names the missing buffer: " << error;
}

TEST(GltfFile, AMissingFileOrADirectoryIsAnError) {
  EXPECT_EQ(errorOf([] { loadGltfFile("/no/such/scene.gltf", {}); }), "/no/such/scene.gltf: no such file");
  const std::string directory = scratch("").string();
  EXPECT_NE(errorOf([&] { loadGltfFile(directory, {}); }).find("is a directory"), std::string::npos);
}

TEST(GltfFile, MalformedJsonNamesTheFileLineAndColumn) {
  const fs::path path = scratch("malformed.gltf");
  writeFile(path, "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [ {\"mesh\": 0}, ]\n}\n");
  const std::string error = errorOf([&] { loadGltfFile(path.string(), {}); });
  EXPECT_NE(error.find(path.string() + ": not valid JSON: parse error at line 3, column"), std::string::npos) << error;
}

TEST(GltfFile, WrongJsonTypesAreErrorsNamingTheirPath) {
  GltfBuilder b = quadScene();
  b.doc()["nodes"][0]["translation"] = {1, 2};
  EXPECT_EQ(errorOf([&] { b.load(); }),
            "test: nodes[0].translation: expected an array of 3 numbers, found an array [1,2]");
  b.doc()["nodes"][0]["translation"] = {1, 2, "3"};
  EXPECT_EQ(errorOf([&] { b.load(); }), "test: nodes[0].translation[2]: expected a number, found the string \"3\"");
  b.doc()["nodes"][0].erase("translation");
  b.doc()["asset"]["version"] = "1.0";
  EXPECT_EQ(errorOf([&] { b.load(); }), "test: asset.version is \"1.0\"; raylab reads glTF 2.0");
  b.doc().erase("asset");
  EXPECT_EQ(errorOf([&] { b.load(); }), "test: top level: the required property 'asset' is missing");
}

TEST(GltfFile, RequiredExtensionsRaylabLacksAreErrorsAndUsedOnesAWarning) {
  GltfBuilder b = quadScene();
  b.doc()["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_materials_ior", "KHR_texture_transform",
                                "KHR_materials_clearcoat", "KHR_materials_dispersion"};
  WarningCapture warnings;
  b.load();
  EXPECT_EQ(warnings.count("the extension EXT_meshopt_compression"), 1);
  EXPECT_EQ(warnings.count("KHR_materials_dispersion"), 0) << "raylab reads KHR_materials_dispersion";
  EXPECT_EQ(warnings.count("KHR_materials_clearcoat"), 0) << "raylab reads KHR_materials_clearcoat";
  EXPECT_EQ(warnings.count("KHR_materials_ior"), 0) << "raylab reads KHR_materials_ior";
  EXPECT_EQ(warnings.count("KHR_texture_transform"), 0) << "raylab reads KHR_texture_transform";
  b.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_EQ(errorOf([&] { b.load(); }),
            "test: requires the extension KHR_draco_mesh_compression, which raylab does not support");
}

TEST(GltfFile, AFileWithoutScenesShowsItsRootNodes) {
  GltfBuilder b = quadScene();
  b.doc().erase("scene");
  b.doc().erase("scenes");
  WarningCapture warnings;
  EXPECT_EQ(b.load().instances.size(), 1u);
  EXPECT_EQ(warnings.count("has no scenes; showing every root node"), 1);
}

}  // namespace
}  // namespace raylab::test
