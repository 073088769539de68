// The scene `raylab render` and `raylab view` draw when no file is given: assets/scenes/showcase.gltf, every
// BRDF model side by side, compiled into the binary so that it needs no file on disk.
#pragma once

#include <string>

#include "scene/scene.h"

namespace raylab {

// `camera`: a camera name of the showcase file; empty for its first camera.
Scene makeDefaultScene(const std::string& camera = "");

}  // namespace raylab
