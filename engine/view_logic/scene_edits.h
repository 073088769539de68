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

// Sets the model, carrying over what means the same thing in both (docs/viewer.md, "Switching models"): the
// parameters of the same role in both models' tables (ParamInfo::role): the diffuse colour, the specular colour
// where it weighs a lobe, the roughness through the Beckmann slope and its stated equivalents (an exponent of N.H
// s = 2/alpha^2 - 2, an exponent of R.wo a quarter of that, per axis for anisotropic exponents), eta; and delta,
// the texture and the emission. Every other parameter takes the new model's default.
void switchModel(gpu::MaterialRecord& record, std::uint32_t model);

}  // namespace raylab
