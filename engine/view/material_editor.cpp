#include "view/material_editor.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"
#include "measured/nbrdf.h"
#include "util/error.h"
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

// The files a user may pick for a parameter of `role`: those of its kind (.binary MERL files, .h5 networks) in the
// current directory and in the folders of the files already loaded (a scene's own folder once it names one), at
// most kMaxListed, by name.
constexpr std::size_t kMaxListed = 64;

std::vector<std::string> measuredCandidates(std::string_view role) {
  const std::string extension = fileKindExtension(role);
  std::set<std::filesystem::path> folders = {std::filesystem::current_path()};
  for (std::uint32_t id = 1; id <= measuredFileCount(); ++id) {
    folders.insert(std::filesystem::path(measuredFilePath(id)).parent_path());
  }
  std::set<std::string> files;
  for (const std::filesystem::path& folder : folders) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      if (files.size() >= kMaxListed) break;
      const bool kind = role == "network" ? isNbrdfPath(entry.path().string()) : entry.path().extension() == extension;
      if (kind && entry.is_regular_file(error)) {
        files.insert(std::filesystem::absolute(entry.path()).lexically_normal().string());
      }
    }
  }
  return {files.begin(), files.end()};
}

// A file parameter: the file's name, and a list to pick another from (scanned when opened). A file that fails its
// checks is not taken; its message stays under the list until the next pick.
bool drawFileParam(gpu::MaterialRecord& record, const ParamInfo& param) {
  static std::string problem;
  const std::string current = fileParamPath(record, param);
  const std::string extension = fileKindExtension(param.role);
  const std::string shown =
      current.empty() ? "(pick a " + extension + " file)" : std::filesystem::path(current).filename().string();
  bool changed = false;
  if (ImGui::BeginCombo(std::string(param.name).c_str(), shown.c_str())) {
    const std::vector<std::string> candidates = measuredCandidates(param.role);
    if (candidates.empty()) ImGui::TextDisabled("no %s file here or beside the loaded ones", extension.c_str());
    for (const std::string& path : candidates) {
      if (ImGui::Selectable(std::filesystem::path(path).filename().string().c_str(), path == current) && path != current) {
        try {
          setFileParam(record, param.name, path, "panel");
          problem.clear();
          changed = true;
        } catch (const Error& error) {
          problem = error.what();
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered() && !current.empty()) ImGui::SetTooltip("%s", current.c_str());
  if (!problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
  return changed;
}

}  // namespace

bool drawMaterialEditor(gpu::MaterialRecord& record) {
  bool changed = false;
  const ModelInfo& current = modelInfo(record.model);
  if (ImGui::BeginCombo("model", std::string(current.name).c_str())) {
    for (const ModelInfo& model : allModels()) {
      const bool selected = model.id == record.model;
      // A model that reads a file can be chosen once a file is loaded (then it takes the last one): the first comes
      // from its file list below, or from --compare, a scene or Python.
      const ParamInfo* fileParam = findFileParam(model);
      const bool needsFile = fileParam != nullptr && latestMeasuredFile(fileParam->role) == kNoMeasuredFile;
      if (needsFile) {
        gpu::MaterialRecord candidate = record;
        const std::vector<std::string> files = measuredCandidates(fileParam->role);
        ImGui::BeginDisabled(files.empty());
        if (ImGui::Selectable(std::string(model.name).c_str(), selected) && !selected) {
          try {
            switchModel(candidate, model.id);
            setFileParam(candidate, fileParam->name, files.front(), "panel");
            record = candidate;
            changed = true;
          } catch (const Error&) {
            // the file list under the model shows why, once a file of it is picked
          }
        }
        ImGui::EndDisabled();
        if (files.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
          ImGui::SetTooltip(fileParam->role == std::string_view("network")
                                ? "no .h5 neural BRDF in the current directory or beside the loaded files"
                                : "no .binary file in the current directory: make one with raylab brdf tabulate");
        }
        continue;
      }
      if (ImGui::Selectable(std::string(model.name).c_str(), selected) && !selected) {
        switchModel(record, model.id);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  // A layered model's parameters (openpbr's base_, specular_, coat_) under one collapsible header per layer.
  std::string_view layer;
  bool open = true;
  for (const ParamInfo& param : modelInfo(record.model).params) {
    const std::string_view paramsLayer = paramLayer(modelInfo(record.model), param);
    if (!paramsLayer.empty() && paramsLayer != layer) {
      layer = paramsLayer;
      std::string heading(layer);
      std::replace(heading.begin(), heading.end(), '_', ' ');  // "thin film"
      open = ImGui::CollapsingHeader(heading.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
    }
    if (!open) continue;
    changed |= isFileParam(param) ? drawFileParam(record, param) : drawParam(record, param);
  }
  changed |= drawParam(record, deltaParam());
  return changed;
}

}  // namespace raylab
