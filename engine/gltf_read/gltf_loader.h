// glTF 2.0 scenes (.gltf and .glb) into the host Scene. The conventions (units, cameras, lights, the
// extras.raylab materials and spheres, the metallic-roughness mapping, defaults and repairs) are in
// docs/scenes.md. Every error is a raylab::Error whose message starts with the file and names the node,
// mesh, accessor or material at fault; repairs and ignored features are reported once each through warn().
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace raylab {

struct GltfOptions {
  std::string camera;  // --camera NAME: a camera's or its node's name; empty: the first perspective camera
  bool allowOutsideUris = false;  // --allow-outside-uris: buffers and images may lie outside the file's folder
  std::string environment;  // --env FILE.exr: replaces the file's extras.raylab.environment
  std::optional<float> environmentStrength;  // --env-strength S: replaces its strength
  std::optional<float> environmentRotation;  // --env-rotation DEGREES about +Y: replaces its rotation
  // The device's maxStorageBufferRange when known: an environment image too large for it is refused from its header.
  std::uint64_t maxBufferBytes = std::numeric_limits<std::uint64_t>::max();
};

// Loads the default scene of a .gltf or .glb file (told apart by content). Scene.name is the file's stem.
Scene loadGltfFile(const std::string& path, const GltfOptions& options);

// Loads glTF JSON text held in memory (the built-in default scene). External URIs resolve against
// `baseDirectory`; `sceneName` becomes Scene.name and starts every message.
Scene loadGltfText(const std::string& json, const std::string& baseDirectory, const std::string& sceneName,
                   const GltfOptions& options);

}  // namespace raylab
