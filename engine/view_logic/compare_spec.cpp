#include "view_logic/compare_spec.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "brdf_params/material_params.h"
#include "util/error.h"

namespace raylab {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  return parts;
}

std::string materialNames(const Scene& scene) {
  std::string names;
  for (const Material& material : scene.materials) names += (names.empty() ? "'" : ", '") + material.name + "'";
  return names;
}

std::string modelNames() {
  std::string names;
  for (const ModelInfo& model : allModels()) names += (names.empty() ? "" : ", ") + std::string(model.name);
  return names;
}

float parseFloat(const std::string& word, const std::string& where) {
  float value = 0.0f;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
    throw Error(where + ": '" + word + "' is not a number", kExitUsage);
  }
  return value;
}

}  // namespace

CompareSpec parseCompareSpec(const std::string& text, const Scene& scene, const std::string& where) {
  const std::size_t equals = text.rfind('=', text.find(':'));
  if (equals == std::string::npos || equals == 0) {
    throw Error(where + ": '" + text + "' is not MATERIAL=MODEL[:k=v,...] (materials: " + materialNames(scene) + ")",
                kExitUsage);
  }
  const std::string materialName = text.substr(0, equals);
  const std::size_t colon = text.find(':', equals);
  const std::string modelName = text.substr(equals + 1, colon == std::string::npos ? std::string::npos : colon - equals - 1);

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
  const ModelInfo* model = findModel(modelName);
  if (model == nullptr) {
    throw Error(where + ": '" + modelName + "' is not a BRDF model (models: " + modelNames() + ")", kExitUsage);
  }
  const gpu::MaterialRecord& original = scene.materials[spec.material].record;
  spec.record = defaultRecord(model->id);
  spec.record.delta = original.delta;
  spec.record.baseColorTexture = original.baseColorTexture;
  spec.record.emission = original.emission;
  if (colon != std::string::npos) {
    for (const std::string& assignment : split(text.substr(colon + 1), ',')) {
      const std::size_t sign = assignment.find('=');
      if (sign == std::string::npos) {
        throw Error(where + ": '" + assignment + "' is not k=v", kExitUsage);
      }
      const std::string name = assignment.substr(0, sign);
      const std::vector<std::string> channels = split(assignment.substr(sign + 1), '/');
      if (channels.size() != 1 && channels.size() != 3) {
        throw Error(where + ": " + name + " takes one value or r/g/b", kExitUsage);
      }
      glm::vec3 value(parseFloat(channels[0], where + ": " + name));
      if (channels.size() == 3) {
        value = glm::vec3(value.x, parseFloat(channels[1], where + ": " + name), parseFloat(channels[2], where + ": " + name));
      }
      try {
        setParam(spec.record, name, value, where);
      } catch (const Error& error) {
        throw Error(error.what(), kExitUsage);
      }
    }
  }
  return spec;
}

std::string describeRecord(const gpu::MaterialRecord& record) {
  std::string text = describeModelParams(record);
  if (record.delta > 0.0f) text += " delta=" + formatParamValue(glm::vec3(record.delta), false);
  return text;
}

}  // namespace raylab
