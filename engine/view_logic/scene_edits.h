// Edits the viewer makes to a loaded scene, shared by the panel and by scripts: find by name, switch a
// material's BRDF model, move and dim lights. Only values change, never counts, so the device buffers are
// updated in place (updateMaterials, updateLights) and the acceleration structures stay.
#pragma once

#include <string_view>

#include "scene/scene.h"

namespace raylab {

// Null when there is no such name.
Material* findMaterial(Scene& scene, std::string_view name);
Light* findLight(Scene& scene, std::string_view name);

// Sets the model; every parameter of the new model whose current value is outside its range (or not finite)
// takes its default, so a record that came from another model is always valid.
void switchModel(gpu::MaterialRecord& record, std::uint32_t model);

}  // namespace raylab
