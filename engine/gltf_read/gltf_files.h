// Internal to the glTF loader: what a scene file may make raylab read. A scene is untrusted input (renders may
// run as a service on other people's files), so its URIs resolve only inside the scene's own directory tree,
// only regular files are read (a FIFO would hang, /dev/zero would exhaust memory), sizes are checked before
// reading, and images are decoded only when a material uses them, within documented limits (docs/scenes.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

namespace raylab::gltf {

// Limits of one scene (docs/scenes.md, "Limits").
inline constexpr std::size_t kMaxJsonDepth = 128;                          // nested arrays and objects
inline constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(1) << 31;    // the .gltf or .glb itself
inline constexpr std::uint64_t kMaxExternalFileBytes = std::uint64_t(1) << 30;  // one buffer or image file
inline constexpr std::uint64_t kMaxImageTexels = std::uint64_t(1) << 25;   // one decoded image (e.g. 8192x4096)
inline constexpr std::uint64_t kMaxSceneTexels = std::uint64_t(1) << 25;   // all decoded images together

struct UriPolicy {
  std::filesystem::path root;  // URIs must resolve inside this directory; empty: no external files at all
  bool allowOutside = false;   // --allow-outside-uris: the user trusts the file
  std::string error;           // the first refusal, with its reason, for the message that tinygltf truncates
};

// tinygltf's file-system callbacks under `policy` (which must outlive the load).
tinygltf::FsCallbacks fsCallbacks(UriPolicy& policy);

// An image loader that keeps the encoded bytes and decodes nothing (image.bits == 0 marks them): tinygltf would
// otherwise decode every image in the file, used or not.
bool keepEncodedImage(tinygltf::Image* image, int imageIndex, std::string* error, std::string* warning, int, int,
                      const unsigned char* bytes, int size, void*);

// Throws Error(label: ...) when JSON text nests arrays and objects deeper than kMaxJsonDepth: the parsers and
// destructors downstream recurse once per level.
void checkJsonDepth(const std::string& text, const std::string& label);

// The path of external file `uri` (relative to `baseDirectory`, percent-encoding decoded) if `policy` admits
// it; else throws Error saying why (a URI scheme, outside the scene's folder, a scene held in memory).
std::string resolveUri(const std::string& uri, const std::string& baseDirectory, UriPolicy& policy);


}  // namespace raylab::gltf
