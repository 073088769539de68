// A sweep's row as a glTF 2.0 text file, written through tinygltf: `raylab sweep --gltf`, which
// tools/scenes/make_scenes.py runs to write the committed sweep scenes, so that the contact sheets and the
// assets come from one layout (sweep_scene.h).
#pragma once

#include <string>

#include "sweep/sweep_scene.h"

namespace raylab {

// Two cameras: "camera", the whole row at 16:9, and "row", one cell tall (the row fills an N:1 image).
// Materials go in extras.raylab (with a pbrMetallicRoughness preview), spheres as extras.raylab.sphere nodes
// carrying a low-poly stand-in mesh for other viewers, the light as KHR_lights_punctual, buffers as data URIs
// (docs/scenes.md). The scene's extras hold the background and `sweep`: the model, parameter, values, bounds
// and the contact sheet's title. Parent directories are created; errors name the file.
void writeSweepGltf(const SweepScene& sweep, const std::string& path);

}  // namespace raylab
