// Hostile scene files: each must end in a clear error naming the file and what was wrong (or load, where the
// file is valid), never in a crash, a hang, the machine's memory or a read outside the scene's folder.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>

#include "gltf_test_support.h"
#include "gltf_read/gltf_files.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = std::uint8_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= std::uint8_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= std::uint8_t(bytes[i + 2]);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

TEST(GltfHostile, ATenThousandLevelNodeChainLoadsWithoutRecursion) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  constexpr int kLevels = 10000;
  b.addNode({{"children", {1}}});
  for (int i = 1; i < kLevels; ++i) {
    json node = {{"translation", {0.0, 0.0, 0.0}}};
    if (i + 1 < kLevels) node["children"] = {i + 1};
    else node["mesh"] = mesh;
    b.addNode(node, false);
  }
  WarningCapture warnings;
  const Scene scene = b.load();
  EXPECT_EQ(scene.instances.size(), 1u);
}

TEST(GltfHostile, JsonNestedDeeperThanTheLimitIsRefusedBeforeParsing) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  std::string text = b.text();
  const std::string deep = std::string(20000, '[') + std::string(20000, ']');
  text.insert(text.rfind('}'), ", \"extras\": " + deep);
  const std::string error = errorOf([&] { loadGltfText(text, "", "test", {}); });
  EXPECT_NE(error.find("test: line "), std::string::npos) << error;
  EXPECT_NE(error.find("nested deeper than 128 levels"), std::string::npos) << error;
}

// 22 levels of nodes that each list the next one twice expanded to 2^22 instances (132 s, 1.95 GB).
TEST(GltfHostile, ANodeListedAsAChildTwiceIsRefusedAtOnce) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.addNode({{"children", {1, 1}}});
  for (int i = 1; i < 40; ++i) {
    b.addNode(i + 1 < 40 ? json{{"children", {i + 1, i + 1}}} : json{{"mesh", mesh}}, false);
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  EXPECT_NE(error.find("test: node 1: is a child of node 0 and again of node 0; glTF allows each node one parent"),
            std::string::npos)
      << error;
}

TEST(GltfHostile, ImagesNoMaterialUsesAreNotDecoded) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  const std::string huge = "data:image/png;base64," + base64(pngHeader(16384, 16384));
  for (int i = 0; i < 12; ++i) b.doc()["images"].push_back({{"uri", huge}});
  const Scene scene = b.load();  // decoding any of them would fail: they hold no pixel data
  EXPECT_TRUE(scene.textures.empty());

  // Used by a material, the same image is refused from its header, naming its size and the limit.
  b.doc()["textures"] = json::array({{{"source", 0}}});
  const int material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  b.doc()["meshes"][0]["primitives"][0]["material"] = material;
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: material 0 baseColorTexture: image 0: is 16384x16384, over raylab's limit of 33554432 texels"),
            std::string::npos)
      << error;
}

TEST(GltfHostile, AMissingImageFileIsNamed) {
  const fs::path dir = freshDir("hostile", "missing_image");
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.doc()["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2");
  b.doc()["images"] = json::array({{{"uri", "nowhere.png"}}});
  b.doc()["textures"] = json::array({{{"source", 0}}});
  b.doc()["meshes"][mesh]["primitives"][0]["material"] =
      b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  b.addNode({{"mesh", mesh}});
  writeFile(dir / "scene.gltf", b.text());
  WarningCapture warnings;
  const std::string error = errorOf([&] { loadGltfFile((dir / "scene.gltf").string(), {}); });
  EXPECT_NE(error.find("image 0 ('nowhere.png')"), std::string::npos) << error;
  EXPECT_NE(error.find("missing or unreadable"), std::string::npos) << error;
  EXPECT_EQ(error.find("-1"), std::string::npos) << error;
}

// A scene whose one buffer lives at `uri`, written to dir/sub/scene.gltf.
fs::path sceneWithBufferUri(const fs::path& dir, const std::string& uri, std::size_t byteLength) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  json doc = json::parse(b.text());
  doc["buffers"][0]["uri"] = uri;
  doc["buffers"][0]["byteLength"] = byteLength;
  fs::create_directories(dir / "sub");
  writeFile(dir / "sub" / "scene.gltf", doc.dump());
  return dir / "sub" / "scene.gltf";
}

std::string bufferBytesOfAQuad() {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  const json doc = json::parse(b.text());
  const std::string uri = doc["buffers"][0]["uri"];
  std::vector<unsigned char> bytes;
  const std::string payload = uri.substr(uri.find(',') + 1);
  // Decode the builder's base64 data URI back to raw bytes.
  static const std::string kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::uint32_t accumulator = 0;
  int bits = 0;
  std::string raw;
  for (char c : payload) {
    const std::size_t digit = kDigits.find(c);
    if (digit == std::string::npos) continue;
    accumulator = (accumulator << 6) | std::uint32_t(digit);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      raw += char((accumulator >> bits) & 0xFF);
    }
  }
  return raw;
}

TEST(GltfHostile, UrisOutsideTheScenesFolderAreRefusedUnlessAllowed) {
  const fs::path dir = freshDir("hostile", "outside");
  const std::string bytes = bufferBytesOfAQuad();
  writeFile(dir / "outside.bin", bytes);
  const fs::path scene = sceneWithBufferUri(dir, "../outside.bin", bytes.size());
  const std::string error = errorOf([&] { loadGltfFile(scene.string(), {}); });
  EXPECT_NE(error.find(scene.string() + ": the URI"), std::string::npos) << error;
  EXPECT_NE(error.find("outside the scene's directory"), std::string::npos) << error;
  EXPECT_NE(error.find("--allow-outside-uris"), std::string::npos) << error;

  GltfOptions trusting;
  trusting.allowOutsideUris = true;
  WarningCapture warnings;
  EXPECT_EQ(loadGltfFile(scene.string(), trusting).instances.size(), 1u);

  // /etc/passwd was read as geometry.
  const fs::path passwd = sceneWithBufferUri(freshDir("hostile", "passwd"), "../../../../../../../../../../etc/passwd", 16);
  EXPECT_NE(errorOf([&] { loadGltfFile(passwd.string(), {}); }).find("outside the scene's directory"),
            std::string::npos);
}

TEST(GltfHostile, AFifoOrADirectoryAsABufferIsRefusedWithoutHanging) {
  const fs::path dir = freshDir("hostile", "special");
  fs::create_directories(dir / "sub");
  ASSERT_EQ(::mkfifo((dir / "sub" / "fifo.bin").c_str(), 0600), 0);
  fs::create_directories(dir / "sub" / "folder.bin");
  const fs::path fifoScene = sceneWithBufferUri(dir, "fifo.bin", 64);
  const std::string fifo = errorOf([&] { loadGltfFile(fifoScene.string(), {}); });
  EXPECT_NE(fifo.find("fifo.bin: is not a regular file"), std::string::npos) << fifo;
  const fs::path folderScene = sceneWithBufferUri(dir, "folder.bin", 64);
  const std::string folder = errorOf([&] { loadGltfFile(folderScene.string(), {}); });
  EXPECT_NE(folder.find("folder.bin: is a directory"), std::string::npos) << folder;
}

TEST(GltfHostile, LightsThatOverflowFloatAreRefused) {
  for (const json& light : {json{{"type", "point"}, {"intensity", 1e39}},
                            json{{"type", "point"}, {"intensity", 1e30}, {"color", {1e30, 1.0, 1.0}}}}) {
    GltfBuilder b;
    b.addNode({{"mesh", b.addQuad()}});
    b.doc()["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {light};
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    const std::string error = errorOf([&] { b.load(); });
    EXPECT_NE(error.find("test: light 0"), std::string::npos) << error;
    EXPECT_NE(error.find("raylab's limit of 1e+20"), std::string::npos) << error;
  }
}

TEST(GltfHostile, ACameraThatCollapsesInFloatIsRefusedNamingIt) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 1e-46}, {"znear", 0.1}}}}};
  b.addNode({{"camera", 0}, {"translation", {0.0, 0.0, 5.0}}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: camera 0: yfov 1e-46 rad is outside [0.0001, 3.1)"), std::string::npos) << error;
}

TEST(GltfHostile, GeometryBeyondFloatPrecisionIsWarnedWithItsExtent) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}, {"scale", {1e8, 1e8, 1.0}}});
  WarningCapture warnings;
  b.load();
  EXPECT_EQ(warnings.count("units from the origin; float32 traversal resolves about"), 1);
}

// The orbit pivot of a glTF camera lies on the scene, not one unit in front of the camera.
TEST(GltfHostile, AGltfCameraOrbitsThePointItLooksAt) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  b.addNode({{"camera", 0}, {"translation", {0.25, 0.25, 10.0}}});
  WarningCapture warnings;
  const Scene scene = b.load();
  EXPECT_NEAR(scene.camera.target.z, 0.0f, 1e-5f) << "the pivot is where the view ray meets the quad";
  EXPECT_NEAR(scene.camera.target.x, 0.25f, 1e-5f);
}

}  // namespace
}  // namespace raylab::test
