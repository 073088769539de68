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

// Parses `text` against `scene`: the material by name, the model, and parameters (k=v, RGB as r/g/b, separated
// by commas) over the model's defaults, delta and the base-colour texture kept from the material. Throws
// Error(kExitUsage) starting with `where`, listing the materials, models or parameters that exist.
CompareSpec parseCompareSpec(const std::string& text, const Scene& scene, const std::string& where);

// "phong rho_d=0.7/0.1/0.1 rho_s=0.3 s=60": a material's model and parameters as the labels show them.
std::string describeRecord(const gpu::MaterialRecord& record);

}  // namespace raylab
