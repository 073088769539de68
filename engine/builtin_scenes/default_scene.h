// The scene `raylab render` and `raylab view` draw when no file is given: assets/scenes/showcase.gltf, every
// BRDF model side by side, compiled into the binary so that it needs no file on disk.
#pragma once

#include <string>

#include "gltf_read/gltf_loader.h"
#include "scene/scene.h"

namespace raylab {

// options.camera: a camera name of the showcase file; empty for its first camera. The environment options
// apply as to a file.
Scene makeDefaultScene(const GltfOptions& options = {});

}  // namespace raylab
