#include "gltf_read/gltf_document.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "gltf_read/gltf_files.h"
#include "util/error.h"
#include "util/log.h"

namespace raylab::gltf {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::size_t kGlbHeaderSize = 12;
constexpr std::size_t kGlbChunkHeaderSize = 8;
// The extensions raylab reads; a file that requires any other cannot be shown faithfully.
const char* const kSupportedExtensions[] = {"KHR_lights_punctual", "KHR_materials_clearcoat",
                                            "KHR_materials_emissive_strength", "KHR_materials_ior",
                                            "KHR_materials_iridescence", "KHR_materials_sheen",
                                            "KHR_materials_volume", "KHR_materials_coat", "KHR_materials_fuzz",
                                            "KHR_materials_diffuse_roughness", "KHR_materials_anisotropy",
                                            "KHR_materials_specular", "KHR_materials_transmission",
                                            "KHR_materials_diffuse_transmission", "KHR_materials_dispersion",
                                            "KHR_texture_transform"};
constexpr std::size_t kMaxFileBytes = std::size_t(1) << 31;  // tinygltf takes sizes as unsigned int

std::uint32_t readU32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, sizeof value);  // GLB is little-endian, as is every target
  return value;
}

bool isGlb(const std::string& bytes) { return bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic; }

// The JSON chunk of a GLB container, with the container's own consistency checks.
std::string glbJson(const std::string& bytes, const std::string& label) {
  if (bytes.size() < kGlbHeaderSize + kGlbChunkHeaderSize) {
    throw Error(label + ": GLB file is truncated (" + std::to_string(bytes.size()) + " bytes)");
  }
  const std::uint32_t version = readU32(bytes, 4);
  if (version != 2) throw Error(label + ": GLB version " + std::to_string(version) + " is not supported (expected 2)");
  const std::uint32_t length = readU32(bytes, 8);
  if (length > bytes.size()) {
    throw Error(label + ": GLB header says " + std::to_string(length) + " bytes but the file has " +
                std::to_string(bytes.size()));
  }
  const std::uint32_t jsonLength = readU32(bytes, kGlbHeaderSize);
  const std::uint32_t jsonType = readU32(bytes, kGlbHeaderSize + 4);
  if (jsonType != kGlbJsonChunk) throw Error(label + ": the first GLB chunk is not JSON");
  if (std::uint64_t(kGlbHeaderSize) + kGlbChunkHeaderSize + jsonLength > length) {
    throw Error(label + ": the GLB JSON chunk (" + std::to_string(jsonLength) +
                " bytes) runs past the end of the file");
  }
  return bytes.substr(kGlbHeaderSize + kGlbChunkHeaderSize, jsonLength);
}

nlohmann::json parseJson(const std::string& text, const std::string& label) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    // nlohmann's messages carry the line and column; strip its "[json.exception...]" prefix.
    std::string what = error.what();
    const std::size_t bracket = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what = what.substr(bracket + 2);
    throw Error(label + ": not valid JSON: " + what);
  }
}

bool isSupported(const std::string& extension) {
  for (const char* supported : kSupportedExtensions) {
    if (extension == supported) return true;
  }
  return false;
}

// Before tinygltf, which would otherwise fail on what a required extension changes (KHR_draco_mesh_compression
// leaves accessors without buffer views) with a message that does not say why.
void checkExtensions(Document& document) {
  if (const auto required = document.json.find("extensionsRequired"); required != document.json.end()) {
    for (const nlohmann::json& name : *required) {
      if (!isSupported(name.get<std::string>())) {
        document.fail("requires the extension " + name.get<std::string>() + ", which raylab does not support");
      }
    }
  }
  if (const auto used = document.json.find("extensionsUsed"); used != document.json.end()) {
    for (const nlohmann::json& name : *used) {
      if (!isSupported(name.get<std::string>())) document.ignore("the extension " + name.get<std::string>());
    }
  }
}

// tinygltf separates messages with newlines; fold them into one line each.
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text) {
    if (c == '\n') c = ';';
  }
  return text;
}

}  // namespace

void Document::fail(const std::string& message) const { throw Error(label + ": " + message); }

void Document::warnOnce(const std::string& key, const std::string& message) {
  if (!warned.insert(key).second) return;
  warn(label + ": " + message);
}

void Document::reportIgnored() const {
  if (ignored.empty()) return;
  std::string list;
  for (const std::string& feature : ignored) list += (list.empty() ? "" : "; ") + feature;
  warn(label + ": ignored what raylab does not support (docs/scenes.md): " + list);
}

std::string describe(std::string_view kind, int index, const std::string& name) {
  std::string text = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) text += " '" + name + "'";
  return text;
}

const nlohmann::json* findPath(const nlohmann::json& object, std::initializer_list<const char*> path) {
  const nlohmann::json* current = &object;
  for (const char* key : path) {
    if (!current->is_object()) return nullptr;
    const auto it = current->find(key);
    if (it == current->end()) return nullptr;
    current = &*it;
  }
  return current;
}

std::string quote(const nlohmann::json& value) {
  const std::string text = value.dump();
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

Document parseDocument(const std::string& bytes, const std::string& baseDirectory, const std::string& label,
                       bool mustBeBinary, bool allowOutsideUris) {
  if (bytes.size() > kMaxFileBytes) throw Error(label + ": the file is larger than 2 GiB");
  const bool binary = isGlb(bytes);
  if (mustBeBinary && !binary) throw Error(label + ": a .glb file must start with the GLB magic 'glTF'");

  Document document;
  document.label = label;
  const std::string jsonText = binary ? glbJson(bytes, label) : bytes;
  checkJsonDepth(jsonText, label);
  document.json = parseJson(jsonText, label);
  checkSchema(document.json, label);
  checkExtensions(document);

  tinygltf::TinyGLTF loader;
  UriPolicy policy;
  policy.allowOutside = allowOutsideUris;
  if (!baseDirectory.empty() || allowOutsideUris) {
    std::error_code error;
    policy.root = std::filesystem::weakly_canonical(baseDirectory.empty() ? "." : baseDirectory, error);
  }
  loader.SetFsCallbacks(fsCallbacks(policy));
  loader.SetImageLoader(&keepEncodedImage, nullptr);
  std::string errors;
  std::string warnings;
  const bool loaded =
      binary ? loader.LoadBinaryFromMemory(&document.model, &errors, &warnings,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()), baseDirectory)
             : loader.LoadASCIIFromString(&document.model, &errors, &warnings, bytes.data(),
                                          static_cast<unsigned int>(bytes.size()), baseDirectory);
  // tinygltf may report an error and still return true (a texture info without its index, for one).
  if (!loaded || !errors.empty()) {
    // The policy's own message says why a file was refused; tinygltf's would only say it was not read.
    if (!policy.error.empty()) throw Error(label + ": " + policy.error);
    throw Error(label + ": " + oneLine(errors.empty() ? "tinygltf could not load the file" : errors));
  }
  if (!warnings.empty()) warn(label + ": " + oneLine(warnings));
  document.baseDirectory = baseDirectory;
  document.uriPolicy = policy;
  document.uriPolicy.error.clear();
  return document;
}

}  // namespace raylab::gltf
