// The panel's editor of one material: its model (a combo box) and a slider per parameter of the contract's table
// (brdf_params/material_params.h), delta included. Used for the scene's materials and the compared side's.
#pragma once

#include "shared/scene_records.h"

namespace raylab {

// Draws the editor into the current ImGui window; true when the record changed.
bool drawMaterialEditor(gpu::MaterialRecord& record);

}  // namespace raylab
