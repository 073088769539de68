// What the viewer's split view compares: MATERIAL=MODEL[:k=v,...], one material of the scene switched to another
// BRDF model and parameters on the right side (`raylab view --compare`, the script's `compare`, the panel).
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace raylab {

struct CompareSpec {
  std::uint32_t material = 0;   // index into scene.materials
  gpu::MaterialRecord record;   // what that material becomes on the right side
};

// Parses `text` against `scene`: the material by name, the model, and parameters (applyParamList's k=v list, ','
// or ';' between them) over the material switched to that model as the panel switches it (switchModel: its
// colours and roughness carried over). Throws
// Error(kExitUsage) starting with `where`, listing the materials, models or parameters that exist.
CompareSpec parseCompareSpec(const std::string& text, const Scene& scene, const std::string& where);

// "phong rho_d=0.7/0.1/0.1 rho_s=0.3 s=60": a material's model and parameters as the labels show them.
std::string describeRecord(const gpu::MaterialRecord& record);

}  // namespace raylab
