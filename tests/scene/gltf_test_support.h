// Helpers for the glTF tests: where the scenes are, warnings captured instead of printed, and small glTF
// documents built in code so that each test states the one feature it exercises.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "gltf_read/gltf_loader.h"
#include "util/error.h"
#include "util/log.h"

namespace raylab::test {

// assets/scenes of this source tree.
std::filesystem::path assetsDirectory();
// Debian's assimp-testmodels glTF 2.0 files (tools/setup.sh installs the package).
std::filesystem::path assimpDirectory();
// Every committed scene, sorted by name.
std::vector<std::filesystem::path> assetFiles();

// An empty scratch directory TempDir()/raylab_gltf_<suite>/<name>, for files a test writes.
std::filesystem::path freshDir(const std::string& suite, const std::string& name);

// A PNG signature and IHDR chunk claiming width x height (8-bit RGB) with no pixel data: enough for the size check
// that comes before decoding.
std::string pngHeader(std::uint32_t width, std::uint32_t height);

// Collects warn() messages while alive, so tests can check them and the log stays quiet.
class WarningCapture {
 public:
  WarningCapture();
  ~WarningCapture();
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;

  const std::vector<std::string>& messages() const { return messages_; }
  // How many messages contain `text`.
  int count(const std::string& text) const;

 private:
  std::vector<std::string> messages_;
  WarningSink previous_;
};

// The message of the raylab::Error that `load` throws, or "" when it returns. Any other exception escapes
// and fails the test.
template <class Load>
std::string errorOf(Load&& load) {
  try {
    load();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// A glTF 2.0 document under construction: one scene, one buffer written as a base64 data URI, and helpers
// that append accessors, meshes, nodes and materials and return their indices. Tests edit doc() directly
// for anything else.
class GltfBuilder {
 public:
  GltfBuilder();

  nlohmann::json& doc() { return doc_; }

  // Appends raw bytes as a buffer view (4-byte aligned) and returns its index.
  int addView(const std::vector<std::uint8_t>& bytes, int byteStride = 0);
  // An accessor over a new buffer view: floats as VEC2/VEC3/..., or indices as unsigned shorts.
  int addFloats(const std::vector<float>& values, const std::string& type);
  int addIndices(const std::vector<std::uint16_t>& indices);
  // A one-primitive mesh; `normals` and `material` are optional (empty, -1).
  int addMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint16_t>& indices, int material = -1,
              const std::vector<glm::vec3>& normals = {});
  // A unit quad in the z = 0 plane facing +z: the smallest mesh a scene can render.
  int addQuad(int material = -1);
  // A node; roots are added to the scene.
  int addNode(const nlohmann::json& node, bool root = true);
  int addMaterial(const nlohmann::json& material);
  int addLight(const nlohmann::json& light);

  // The finished JSON text.
  std::string text() const;
  // loadGltfText of text() as scene "test".
  Scene load(const GltfOptions& options = {}) const;

 private:
  nlohmann::json doc_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace raylab::test
