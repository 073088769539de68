// The scene a command was asked for: a glTF file, or the built-in default scene when no path is given.
#pragma once

#include <string>

#include "scene/scene.h"

namespace raylab {

struct SceneRequest {
  std::string path;    // empty: the built-in default scene
  std::string camera;  // --camera NAME; empty: the file's first camera
};

Scene loadScene(const SceneRequest& request);

}  // namespace raylab
