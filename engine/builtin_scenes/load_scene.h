// The scene a command was asked for: a glTF file, or the built-in default scene when no path is given.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace raylab {

struct SceneRequest {
  std::string path;    // empty: the built-in default scene
  std::string camera;  // --camera NAME; empty: the file's first camera
  bool allowOutsideUris = false;  // --allow-outside-uris (docs/scenes.md)
  std::string environment;        // --env FILE.exr: replaces the scene's environment image
  std::optional<float> environmentStrength;  // --env-strength S
  std::optional<float> environmentRotation;  // --env-rotation DEGREES
  std::uint64_t maxBufferBytes = std::numeric_limits<std::uint64_t>::max();  // the device's, when known (GltfOptions)
};

Scene loadScene(const SceneRequest& request);

// The name loadScene gives the scene (the file's stem, or "showcase"), known before loading: default output
// paths are checked before the work starts.
std::string sceneName(const SceneRequest& request);

}  // namespace raylab
