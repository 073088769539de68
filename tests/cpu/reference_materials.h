// Reference materials for the cpu tests, built through the one parameter table (engine/brdf_params/material_params)
// so that names, ranges and defaults are those users get; unnamed parameters keep their defaults.
#pragma once

#include <cstdio>
#include <vector>
#include <string>
#include <string_view>

#include "reference/brdf_reference.h"
#include "brdf_params/material_params.h"
#include "util/error.h"

namespace raylab::test {

struct ParamValue {
  std::string_view name;
  double value;  // every channel of an RGB parameter
};

inline reference::Material makeMaterial(std::string_view model, const std::vector<ParamValue>& params) {
  const ModelInfo* info = findModel(model);
  if (info == nullptr) throw Error("test material: unknown model '" + std::string(model) + "'");
  gpu::MaterialRecord record = defaultRecord(info->id);
  for (const ParamValue& param : params) {
    setParam(record, param.name, glm::vec3(static_cast<float>(param.value)), "test material " + std::string(model));
  }
  return reference::fromRecord(record);
}

// "cooktorrance m=0.3 eta=1.5": the model and the parameters a test set.
inline std::string materialLabel(std::string_view model, const std::vector<ParamValue>& params) {
  std::string label(model);
  for (const ParamValue& param : params) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", param.value);
    label += " " + std::string(param.name) + "=" + value;
  }
  return label;
}

inline std::string_view modelName(const reference::Material& material) { return modelInfo(material.model).name; }

}  // namespace raylab::test
