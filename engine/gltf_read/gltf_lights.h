// Internal to the glTF loader: KHR_lights_punctual lights, placed by their node's world transform.
#pragma once

#include <glm/glm.hpp>

#include "gltf_read/gltf_document.h"
#include "scene/scene.h"

namespace raylab::gltf {

// Light `lightIndex` of the file's KHR_lights_punctual list as used by node `nodeWhere` ("node 2 'lamp'")
// with world transform `world`: the position is the node's origin, the direction its -Z axis; intensity
// times colour goes to LightRecord.intensity (W/sr for point and spot, W/m² for directional).
Light convertLight(const Document& document, int lightIndex, const glm::mat4& world, const std::string& nodeWhere);

}  // namespace raylab::gltf
