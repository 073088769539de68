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

// A parameter of a reference material by name, in double precision (the table's slot for its model).
inline const ParamInfo& paramOf(const reference::Material& material, std::string_view name) {
  const ParamInfo* param = findParam(modelInfo(material.model), name);
  if (param == nullptr || param->slot == gpu::kNoParam) {
    throw Error("test material: '" + std::string(name) + "' is not a parameter of " + std::string(modelName(material)));
  }
  return *param;
}
inline double scalarParam(const reference::Material& material, std::string_view name) {
  return material.params[paramOf(material, name).slot];
}
inline reference::dvec3 rgbParam(const reference::Material& material, std::string_view name) {
  return reference::paramRgb(material, paramOf(material, name).slot);
}
// Sets a parameter exactly (the parameter table stores float; some tests need unrounded values).
inline void setParamExactly(reference::Material& material, std::string_view name, reference::dvec3 value) {
  const ParamInfo& param = paramOf(material, name);
  for (int c = 0; c < (param.rgb ? 3 : 1); ++c) material.params[param.slot + c] = value[c];
}

}  // namespace raylab::test
