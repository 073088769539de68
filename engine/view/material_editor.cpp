#include "view/material_editor.h"

#include <imgui.h>

#include "brdf_params/material_params.h"
#include "view_logic/scene_edits.h"

namespace raylab {

namespace {

// One slider (or colour editor) per parameter, over the contract's range; log-scale parameters get a
// logarithmic slider. Returns true when the value changed.
bool drawParam(gpu::MaterialRecord& record, const ParamInfo& param) {
  glm::vec3 value = getParam(record, param.name);
  const std::string label(param.name);
  bool changed = false;
  if (param.rgb && param.min == 0.0f && param.max == 1.0f) {
    changed = ImGui::ColorEdit3(label.c_str(), &value.x, ImGuiColorEditFlags_Float);
  } else if (param.rgb) {
    changed = ImGui::SliderFloat3(label.c_str(), &value.x, param.min, param.max, "%.3g", ImGuiSliderFlags_AlwaysClamp);
  } else {
    ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
    if (param.logScale) flags |= ImGuiSliderFlags_Logarithmic;
    changed = ImGui::SliderFloat(label.c_str(), &value.x, param.min, param.max, "%.4g", flags);
    value = glm::vec3(value.x);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s [%g, %g]", std::string(param.meaning).c_str(), param.min, param.max);
  }
  if (changed) {
    value = glm::clamp(value, glm::vec3(param.min), glm::vec3(param.max));
    setParam(record, param.name, value, "panel");
  }
  return changed;
}

}  // namespace

bool drawMaterialEditor(gpu::MaterialRecord& record) {
  bool changed = false;
  const ModelInfo& current = modelInfo(record.model);
  if (ImGui::BeginCombo("model", std::string(current.name).c_str())) {
    for (const ModelInfo& model : allModels()) {
      const bool selected = model.id == record.model;
      if (ImGui::Selectable(std::string(model.name).c_str(), selected) && !selected) {
        switchModel(record, model.id);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  for (const ParamInfo& param : modelInfo(record.model).params) changed |= drawParam(record, param);
  changed |= drawParam(record, deltaParam());
  return changed;
}

}  // namespace raylab
