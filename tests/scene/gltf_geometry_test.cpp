// Accessors into triangle meshes: attribute types, byte ranges and strides, indices, primitive modes, sparse
// accessors, and the repairs of missing or broken normals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "gltf_test_support.h"

namespace raylab::test {
namespace {

using nlohmann::json;

const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<std::uint16_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

std::string loadError(const GltfBuilder& b) {
  return errorOf([&] { b.load(); });
}

TEST(GltfGeometry, AnIndexedMeshLoadsWithItsNormalsAndUvs) {
  GltfBuilder b;
  const int mesh = b.addMesh(kQuad, kQuadIndices, -1, std::vector<glm::vec3>(4, {0, 0, 1}));
  b.doc()["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2");
  b.addNode({{"mesh", mesh}});
  const Scene scene = b.load();
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  EXPECT_EQ(m.positions, kQuad);
  EXPECT_EQ(m.normals, std::vector<glm::vec3>(4, {0, 0, 1}));
  EXPECT_EQ(m.uvs, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(GltfGeometry, WithoutNormalsTheKernelUsesFlatGeometricNormals) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  WarningCapture warnings;
  const Scene scene = b.load();
  EXPECT_TRUE(scene.meshes[0].normals.empty());
  EXPECT_EQ(warnings.count("normal"), 0) << "missing normals are legal glTF, not a repair";
}

TEST(GltfGeometry, BrokenNormalsAreRepairedWithOneWarning) {
  GltfBuilder b;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  b.addNode({{"mesh", b.addMesh(kQuad, kQuadIndices, -1, {{0, 0, 0}, {0, 0, 0.5f}, {nan, 0, 1}, {0, 0, 1}})}});
  WarningCapture warnings;
  const Scene scene = b.load();
  for (const glm::vec3& n : scene.meshes[0].normals) {
    EXPECT_NEAR(n.x, 0.0f, 1e-6f);
    EXPECT_NEAR(n.y, 0.0f, 1e-6f);
    EXPECT_NEAR(n.z, 1.0f, 1e-6f) << "zero and NaN normals take their faces' normal, short ones are normalised";
  }
  EXPECT_EQ(warnings.count("repaired 2 zero or non-finite normals"), 1);
  EXPECT_EQ(warnings.count("1 non-unit normals (normalised)"), 1);

  // A vertex no triangle uses keeps the mesh's normals: its own is never interpolated.
  GltfBuilder unused;
  std::vector<glm::vec3> positions = kQuad;
  positions.push_back({5, 5, 5});
  unused.addNode({{"mesh", unused.addMesh(positions, kQuadIndices, -1,
                                          {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {nan, nan, nan}})}});
  const Scene kept = unused.load();
  ASSERT_EQ(kept.meshes[0].normals.size(), 5u);
  EXPECT_EQ(kept.meshes[0].normals[4], glm::vec3(0, 0, 1));
}

TEST(GltfGeometry, NonFinitePositionsAreAnErrorNamingTheAccessor) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addMesh({{0, 0, 0}, {std::numeric_limits<float>::infinity(), 0, 0}, {0, 1, 0}}, {0, 1, 2})}});
  const std::string error = loadError(b);
  EXPECT_NE(error.find("test: accessor 0 (POSITION of mesh 0 primitive 0): position 1 is not finite (inf, 0, 0)"),
            std::string::npos) << error;
}

TEST(GltfGeometry, IndicesOutOfRangeAreAnError) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addMesh(kQuad, {0, 1, 9})}});
  const std::string error = loadError(b);
  EXPECT_NE(
      error.find("accessor 1 (indices of mesh 0 primitive 0): index 9 at position 2 is out of range (4 vertices)"),
      std::string::npos)
      << error;
}

TEST(GltfGeometry, AccessorTypesAreCheckedPerAttribute) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.addNode({{"mesh", mesh}});
  b.doc()["accessors"][0]["componentType"] = 5123;  // POSITION as unsigned short
  std::string error = loadError(b);
  EXPECT_NE(
      error.find("accessor 0 (POSITION of mesh 0 primitive 0): is VEC3 of unsigned short; expected VEC3 of float"),
      std::string::npos)
      << error;

  GltfBuilder uv;
  const int quad = uv.addQuad();
  const int view = uv.addView({0, 0, 255, 0, 255, 255, 0, 255});
  uv.doc()["accessors"].push_back({{"bufferView", view}, {"componentType", 5121}, {"count", 4}, {"type", "VEC2"},
                                   {"normalized", true}});
  uv.doc()["meshes"][quad]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv.doc()["accessors"].size() - 1;
  uv.addNode({{"mesh", quad}});
  EXPECT_EQ(uv.load().meshes[0].uvs, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}))
      << "normalized unsigned bytes map to [0, 1]";
  uv.doc()["accessors"].back()["normalized"] = false;
  error = loadError(uv);
  EXPECT_NE(error.find("(TEXCOORD_0 of mesh 0 primitive 0): integer components must be normalized"), std::string::npos)
      << error;
  uv.doc()["accessors"].back()["normalized"] = true;
  uv.doc()["accessors"].back()["type"] = "VEC3";
  error = loadError(uv);
  EXPECT_NE(error.find("is VEC3 of unsigned byte; expected VEC2 of float or unsigned byte or unsigned short"),
            std::string::npos) << error;
}

TEST(GltfGeometry, ByteRangesAreCheckedAgainstViewsAndBuffers) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["accessors"][0]["byteOffset"] = 8;  // 4 VEC3 floats from byte 8 need 56 bytes; the view has 48
  std::string error = loadError(b);
  EXPECT_NE(error.find("accessor 0 (POSITION of mesh 0 primitive 0): 4 elements of 12 bytes (stride 12, offset 8) "
                       "need 56 bytes, but buffer view 0 has 48"),
            std::string::npos) << error;

  GltfBuilder view;
  view.addNode({{"mesh", view.addQuad()}});
  view.doc()["bufferViews"][0]["byteOffset"] = 1000;
  error = loadError(view);
  EXPECT_NE(error.find("buffer view 0 (bytes 1000 to 1048) runs past the end of buffer 0"), std::string::npos) << error;

  // The count comes from the file: a huge one is a range error, not an attempt to allocate it.
  GltfBuilder huge;
  huge.addNode({{"mesh", huge.addQuad()}});
  huge.doc()["accessors"][0]["count"] = 2147483647;
  error = loadError(huge);
  EXPECT_NE(error.find("2147483647 elements of 12 bytes"), std::string::npos) << error;

  GltfBuilder stride;
  stride.addNode({{"mesh", stride.addQuad()}});
  stride.doc()["bufferViews"][0]["byteStride"] = 8;
  error = loadError(stride);
  EXPECT_NE(error.find("buffer view 0 has byteStride 8, less than the 12-byte element"), std::string::npos) << error;
}

TEST(GltfGeometry, InterleavedAttributesAreReadWithTheirStride) {
  GltfBuilder b;
  // Position and normal interleaved: 24 bytes per vertex.
  std::vector<float> interleaved;
  for (const glm::vec3& p : kQuad) interleaved.insert(interleaved.end(), {p.x, p.y, p.z, 0, 0, 1});
  std::vector<std::uint8_t> bytes(interleaved.size() * sizeof(float));
  std::memcpy(bytes.data(), interleaved.data(), bytes.size());
  const int view = b.addView(bytes, 24);
  b.doc()["accessors"].push_back({{"bufferView", view}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  b.doc()["accessors"].push_back(
      {{"bufferView", view}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  const int indices = b.addIndices(kQuadIndices);
  const json primitive = {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", indices}};
  b.doc()["meshes"].push_back({{"primitives", {primitive}}});
  b.addNode({{"mesh", 0}});
  const Scene scene = b.load();
  EXPECT_EQ(scene.meshes[0].positions, kQuad);
  EXPECT_EQ(scene.meshes[0].normals, std::vector<glm::vec3>(4, {0, 0, 1}));
}

TEST(GltfGeometry, StripsAndFansBecomeTriangleLists) {
  GltfBuilder b;
  const int strip = b.addMesh(kQuad, {0, 1, 3, 2});
  b.doc()["meshes"][strip]["primitives"][0]["mode"] = 5;
  const int fan = b.addMesh(kQuad, {0, 1, 2, 3});
  b.doc()["meshes"][fan]["primitives"][0]["mode"] = 6;
  b.addNode({{"mesh", strip}});
  b.addNode({{"mesh", fan}});
  const Scene scene = b.load();
  // The strip's second triangle swaps its first two vertices, so both face +z like the fan's.
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 3, 3, 1, 2}));
  EXPECT_EQ(scene.meshes[1].indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  for (const Mesh& mesh : scene.meshes) {
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
      const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[t + 1]] - mesh.positions[mesh.indices[t]],
                                     mesh.positions[mesh.indices[t + 2]] - mesh.positions[mesh.indices[t]]);
      EXPECT_GT(n.z, 0.0f) << mesh.name << " triangle " << t / 3;
    }
  }
}

TEST(GltfGeometry, PointsAndLinesAreSkippedWithOneWarning) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  json points = b.doc()["meshes"][mesh]["primitives"][0];
  points["mode"] = 0;
  json lines = points;
  lines["mode"] = 1;
  b.doc()["meshes"][mesh]["primitives"].push_back(points);
  b.doc()["meshes"][mesh]["primitives"].push_back(lines);
  b.addNode({{"mesh", mesh}});
  WarningCapture warnings;
  const Scene scene = b.load();
  EXPECT_EQ(scene.meshes.size(), 1u) << "only the triangles remain";
  EXPECT_EQ(warnings.count("points and lines"), 1);

  b.doc()["meshes"][mesh]["primitives"].erase(0);
  const std::string error = loadError(b);
  EXPECT_NE(error.find("nothing to render (no triangle meshes or raylab spheres; ignored: points and lines"),
            std::string::npos) << error;
}

TEST(GltfGeometry, ATriangleListOfTheWrongLengthIsAnError) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addMesh(kQuad, {0, 1, 2, 3})}});
  const std::string error = loadError(b);
  EXPECT_NE(error.find("mesh 0 primitive 0: a triangle list of 4 vertices (not a multiple of 3)"), std::string::npos)
      << error;
}

TEST(GltfGeometry, SparseAccessorsReplaceTheirElements) {
  GltfBuilder b;
  const int mesh = b.addMesh({{0, 0, 0}, {1, 0, 0}, {5, 5, 5}, {0, 1, 0}}, kQuadIndices);
  const int indices = b.addView({2, 0});  // one unsigned short: element 2
  std::vector<std::uint8_t> value(12);
  const float replacement[3] = {1, 1, 0};
  std::memcpy(value.data(), replacement, sizeof replacement);
  const int values = b.addView(value);
  b.doc()["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", indices}, {"componentType", 5123}}},
                                       {"values", {{"bufferView", values}}}};
  b.addNode({{"mesh", mesh}});
  EXPECT_EQ(b.load().meshes[0].positions, kQuad);

  b.doc()["accessors"][0]["sparse"]["count"] = 9;
  const std::string error = loadError(b);
  EXPECT_NE(error.find("sparse: count 9 exceeds the accessor's 4 elements"), std::string::npos) << error;
}

TEST(GltfGeometry, MorphTargetsAreIgnoredWithAWarning) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.doc()["meshes"][mesh]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
  b.addNode({{"mesh", mesh}});
  WarningCapture warnings;
  b.load();
  EXPECT_EQ(warnings.count("morph targets"), 1);
}

TEST(GltfGeometry, ZeroAreaTrianglesAreDropped) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0, 1, 3})}});
  WarningCapture warnings;
  EXPECT_EQ(b.load().meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 3}));
  EXPECT_EQ(warnings.count("dropped 1 triangles of zero area"), 1);
}

}  // namespace
}  // namespace raylab::test
