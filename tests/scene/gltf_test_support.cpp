#include "gltf_test_support.h"

#include <algorithm>
#include <cstring>

#include <gtest/gtest.h>

#include "util/error.h"

namespace raylab::test {

std::filesystem::path freshDir(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / ("raylab_gltf_" + suite) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t chunk = (std::uint32_t(bytes[i]) << 16) |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
    out += kAlphabet[(chunk >> 18) & 63];
    out += kAlphabet[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return out;
}

template <class T>
std::vector<std::uint8_t> bytesOf(const std::vector<T>& values) {
  std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// Warnings that a test does not capture are expected side effects (the defaults for a test file without a
// camera or lights); dropping them keeps the log to what failed. WarningCapture still sees everything.
class QuietWarnings : public ::testing::Environment {
 public:
  void SetUp() override { setWarningSink([](const std::string&) {}); }
  void TearDown() override { setWarningSink(nullptr); }
};

[[maybe_unused]] const ::testing::Environment* const kQuietWarnings =
    ::testing::AddGlobalTestEnvironment(new QuietWarnings);

}  // namespace

std::filesystem::path assetsDirectory() { return std::filesystem::path(RAYLAB_SOURCE_DIR) / "assets" / "scenes"; }

std::filesystem::path assimpDirectory() { return RAYLAB_ASSIMP_GLTF_DIR; }

std::vector<std::filesystem::path> assetFiles() {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(assetsDirectory())) return files;  // the tests then fail, naming it
  for (const auto& entry : std::filesystem::directory_iterator(assetsDirectory())) {
    if (entry.path().extension() == ".gltf") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

WarningCapture::WarningCapture()
    : previous_(setWarningSink([this](const std::string& message) { messages_.push_back(message); })) {}

WarningCapture::~WarningCapture() { setWarningSink(previous_); }

int WarningCapture::count(const std::string& text) const {
  return static_cast<int>(std::count_if(messages_.begin(), messages_.end(),
                                        [&](const std::string& m) { return m.find(text) != std::string::npos; }));
}

GltfBuilder::GltfBuilder() {
  doc_ = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};
}

int GltfBuilder::addView(const std::vector<std::uint8_t>& bytes, int byteStride) {
  while (buffer_.size() % 4 != 0) buffer_.push_back(0);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", buffer_.size()}, {"byteLength", bytes.size()}};
  if (byteStride != 0) view["byteStride"] = byteStride;
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  doc_["bufferViews"].push_back(view);
  return static_cast<int>(doc_["bufferViews"].size() - 1);
}

int GltfBuilder::addFloats(const std::vector<float>& values, const std::string& type) {
  const std::size_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
  const int view = addView(bytesOf(values));
  doc_["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", values.size() / components}, {"type", type}});
  return static_cast<int>(doc_["accessors"].size() - 1);
}

int GltfBuilder::addIndices(const std::vector<std::uint16_t>& indices) {
  const int view = addView(bytesOf(indices));
  doc_["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}});
  return static_cast<int>(doc_["accessors"].size() - 1);
}

int GltfBuilder::addMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint16_t>& indices,
                         int material, const std::vector<glm::vec3>& normals) {
  const auto flatten = [](const std::vector<glm::vec3>& vectors) {
    std::vector<float> values;
    for (const glm::vec3& v : vectors) values.insert(values.end(), {v.x, v.y, v.z});
    return values;
  };
  nlohmann::json primitive = {{"attributes", {{"POSITION", addFloats(flatten(positions), "VEC3")}}},
                              {"indices", addIndices(indices)}};
  if (!normals.empty()) primitive["attributes"]["NORMAL"] = addFloats(flatten(normals), "VEC3");
  if (material >= 0) primitive["material"] = material;
  doc_["meshes"].push_back({{"primitives", {primitive}}});
  return static_cast<int>(doc_["meshes"].size() - 1);
}

int GltfBuilder::addQuad(int material) {
  return addMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3}, material);
}

int GltfBuilder::addNode(const nlohmann::json& node, bool root) {
  doc_["nodes"].push_back(node);
  const int index = static_cast<int>(doc_["nodes"].size() - 1);
  if (root) doc_["scenes"][0]["nodes"].push_back(index);
  return index;
}

int GltfBuilder::addMaterial(const nlohmann::json& material) {
  doc_["materials"].push_back(material);
  return static_cast<int>(doc_["materials"].size() - 1);
}

int GltfBuilder::addLight(const nlohmann::json& light) {
  doc_["extensionsUsed"] = {"KHR_lights_punctual"};
  doc_["extensions"]["KHR_lights_punctual"]["lights"].push_back(light);
  return static_cast<int>(doc_["extensions"]["KHR_lights_punctual"]["lights"].size() - 1);
}

std::string GltfBuilder::text() const {
  nlohmann::json doc = doc_;
  if (!buffer_.empty()) {
    doc["buffers"] = {{{"byteLength", buffer_.size()},
                       {"uri", "data:application/octet-stream;base64," + base64(buffer_)}}};
  }
  return doc.dump(1);
}

Scene GltfBuilder::load(const GltfOptions& options) const { return loadGltfText(text(), "", "test", options); }

std::string pngHeader(std::uint32_t width, std::uint32_t height) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  const auto be32 = [&](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((v >> shift) & 0xFF);
  };
  be32(13);
  bytes += "IHDR";
  be32(width);
  be32(height);
  bytes += std::string("\x08\x02\x00\x00\x00", 5);
  be32(0);  // CRC, which stb does not check
  return bytes;
}

}  // namespace raylab::test
