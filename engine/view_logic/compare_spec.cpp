#include "view_logic/compare_spec.h"

#include <cstdio>

#include "brdf_params/material_params.h"
#include "util/error.h"
#include "view_logic/scene_edits.h"

namespace raylab {

namespace {

std::string materialNames(const Scene& scene) {
  std::string names;
  for (const Material& material : scene.materials) names += (names.empty() ? "'" : ", '") + material.name + "'";
  return names;
}

}  // namespace

CompareSpec parseCompareSpec(const std::string& text, const Scene& scene, const std::string& where) {
  const std::string form = "MATERIAL=MODEL[:k=v,...] (materials: " + materialNames(scene) + "; models: " +
                           modelNames() + ")";
  if (text.empty()) throw Error(where + ": empty; expected " + form, kExitUsage);
  // The material is what precedes the first '=' that is followed by a model's name and then the end, ':', ',' or
  // ';' (material names may hold '='; "MATERIAL=MODEL;k=v" is read as meant).
  std::size_t equals = std::string::npos, paramsAt = std::string::npos;
  const ModelInfo* model = nullptr;
  for (std::size_t at = text.find('='); at != std::string::npos && model == nullptr; at = text.find('=', at + 1)) {
    for (const ModelInfo& candidate : allModels()) {
      const std::size_t end = at + 1 + candidate.name.size();
      if (text.compare(at + 1, candidate.name.size(), candidate.name) == 0 &&
          (end == text.size() || text[end] == ':' || text[end] == ',' || text[end] == ';')) {
        equals = at, model = &candidate, paramsAt = end;
      }
    }
  }
  if (model == nullptr) {
    const std::size_t first = text.find('=');
    if (first == std::string::npos || first == 0) throw Error(where + ": '" + text + "' is not " + form, kExitUsage);
    const std::string name = text.substr(0, first);
    bool known = false;
    for (const Material& material : scene.materials) known |= material.name == name;
    if (!known) {
      throw Error(where + ": the scene has no material '" + name + "' (materials: " + materialNames(scene) + ")",
                  kExitUsage);
    }
    const std::string rest = text.substr(first + 1);
    throw Error(where + ": '" + rest.substr(0, rest.find_first_of(":,;")) + "' is not a BRDF model (models: " +
                    modelNames() + ")",
                kExitUsage);
  }
  const std::string materialName = text.substr(0, equals);
  CompareSpec spec;
  bool found = false;
  for (std::uint32_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == materialName) {
      spec.material = i;
      found = true;
      break;
    }
  }
  if (!found) {
    throw Error(where + ": the scene has no material '" + materialName + "' (materials: " + materialNames(scene) + ")",
                kExitUsage);
  }
  // From the material as it is, switched as the panel switches it: its colours carry over to the other model.
  spec.record = scene.materials[spec.material].record;
  switchModel(spec.record, model->id);
  try {
    // Name the material and the model: a command line may carry several overrides.
    if (paramsAt < text.size()) {
      applyParamList(spec.record, std::string_view(text).substr(paramsAt + 1),
                     where + " '" + materialName + "' (" + std::string(model->name) + ")");
    }
    checkFileParams(spec.record, where + " '" + materialName + "' (" + std::string(model->name) + ")");
  } catch (const Error& error) {
    throw Error(error.what(), kExitUsage);
  }
  return spec;
}

std::string describeRecord(const gpu::MaterialRecord& record) {
  std::string text = describeModelParams(record);
  if (record.delta > 0.0f) text += " delta=" + formatParamValue(glm::vec3(record.delta), false);
  return text;
}

}  // namespace raylab
