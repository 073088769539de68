// Internal to the glTF loader: the file's root-level extras.raylab.environment = {"uri": "FILE.exr",
// "strength": S, "rotation": degrees}, with --env, --env-strength and --env-rotation taking its place
// (docs/integrators.md, "Environment light").
#pragma once

#include "scene/environment.h"
#include "gltf_read/gltf_document.h"
#include "gltf_read/gltf_loader.h"

namespace raylab::gltf {

// The environment the file and the options give (hasImage() false when neither names one). Errors name the
// field, the option or the image file.
Environment readEnvironment(Document& document, const GltfOptions& options);

}  // namespace raylab::gltf
