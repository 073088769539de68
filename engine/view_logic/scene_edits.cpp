#include "view_logic/scene_edits.h"

#include <cmath>

#include "brdf_params/material_params.h"

namespace raylab {

Material* findMaterial(Scene& scene, std::string_view name) {
  for (Material& material : scene.materials) {
    if (material.name == name) return &material;
  }
  return nullptr;
}

Light* findLight(Scene& scene, std::string_view name) {
  for (Light& light : scene.lights) {
    if (light.name == name) return &light;
  }
  return nullptr;
}

void switchModel(gpu::MaterialRecord& record, std::uint32_t model) {
  record.model = model;
  for (const ParamInfo& param : modelInfo(model).params) {
    const glm::vec3 value = getParam(record, param.name);
    const int channels = param.rgb ? 3 : 1;
    bool valid = true;
    for (int c = 0; c < channels; ++c) {
      valid &= std::isfinite(value[c]) && value[c] >= param.min && value[c] <= param.max;
    }
    if (!valid) setParam(record, param.name, glm::vec3(param.defaultValue), "switchModel");
  }
}

}  // namespace raylab
