// `raylab brdf models`: the model registry as users and scripts read it (tools/*.py call it with --json instead
// of keeping their own lists). Everything printed comes from the registry's generated table.
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "brdf_commands.h"
#include "brdf_params/material_params.h"
#include "command_line/cli.h"
#include "shared/brdf_lobes.h"
#include "util/error.h"
#include "util/number_text.h"

namespace raylab {

namespace {

std::string lobeNames(std::uint32_t lobes) {
  constexpr std::pair<std::uint32_t, const char*> kNames[] = {
      {gpu::kLobeReflection, "reflection"}, {gpu::kLobeTransmission, "transmission"}, {gpu::kLobeDiffuse, "diffuse"},
      {gpu::kLobeGlossy, "glossy"},         {gpu::kLobeSpecular, "specular"}};
  std::string names;
  for (const auto& [bit, name] : kNames) {
    if (lobes & bit) names += (names.empty() ? "" : " ") + std::string(name);
  }
  return names;
}

nlohmann::ordered_json paramJson(const ParamInfo& p) {
  // A file parameter holds a loaded file's id inside raylab; its users give a path (type "file", no range).
  if (isFileParam(p)) {
    return {{"name", p.name}, {"type", "file"}, {"role", p.role}, {"meaning", p.meaning}};
  }
  return {{"name", p.name},       {"type", p.rgb ? "rgb" : "scalar"}, {"min", p.min},
          {"max", p.max},         {"default", p.defaultValue},        {"scale", p.logScale ? "log" : "linear"},
          {"role", p.role},       {"meaning", p.meaning}};
}

int listModels(bool json) {
  if (json) {
    nlohmann::ordered_json models = nlohmann::ordered_json::array();
    for (const ModelInfo& model : allModels()) {
      nlohmann::ordered_json params = nlohmann::ordered_json::array();
      for (const ParamInfo& p : model.params) params.push_back(paramJson(p));
      params.push_back(paramJson(deltaParam()));
      nlohmann::ordered_json presets = nlohmann::ordered_json::array();
      for (const Preset& preset : model.presets) {
        nlohmann::ordered_json values = nlohmann::ordered_json::object();
        for (const PresetValue& v : preset.values) values[std::string(v.param)] = {v.value.x, v.value.y, v.value.z};
        presets.push_back({{"key", preset.key}, {"name", preset.name}, {"values", values}});
      }
      models.push_back({{"name", model.name},
                        {"lobes", lobeNames(model.lobes)},
                        {"delta_only", isDeltaOnly(model)},
                        {"params", params},
                        {"sweep_base", model.sweepBase},
                        {"presets", presets},
                        {"glsl", model.glslFile},
                        {"reference", model.referenceFile}});
    }
    std::printf("%s\n", models.dump(2).c_str());
    return kExitOk;
  }
  for (const ModelInfo& model : allModels()) {
    std::printf("%s  (%s; %s)\n", std::string(model.name).c_str(), lobeNames(model.lobes).c_str(),
                std::string(model.glslFile).c_str());
    for (const ParamInfo& p : model.params) {
      if (isFileParam(p)) {
        std::printf("  %-8s     PATH of a file  %s\n", std::string(p.name).c_str(), std::string(p.meaning).c_str());
        continue;
      }
      std::printf("  %-8s %-3s [%s, %s] default %s%s  %s\n", std::string(p.name).c_str(), p.rgb ? "rgb" : "",
                  numberText(p.min).c_str(), numberText(p.max).c_str(), numberText(p.defaultValue).c_str(),
                  p.logScale ? ", log scale" : "", std::string(p.meaning).c_str());
    }
    std::string presets;
    for (const Preset& preset : model.presets) {
      presets += (presets.empty() ? std::string(preset.key) + " = " : ", ") + std::string(preset.name);
    }
    if (!presets.empty()) std::printf("  presets: %s\n", presets.c_str());
  }
  const ParamInfo& delta = deltaParam();
  std::printf("every model also has %s [%s, %s] default %s: the %s\n", std::string(delta.name).c_str(),
              numberText(delta.min).c_str(), numberText(delta.max).c_str(), numberText(delta.defaultValue).c_str(),
              std::string(delta.meaning).c_str());
  return kExitOk;
}

}  // namespace

void addBrdfModelsCommand(CLI::App& brdf) {
  auto json = std::make_shared<bool>(false);
  CLI::App* command = addCommand(
      brdf, "models",
      "list the BRDF models and their parameters (names, ranges, defaults, roles)\n"
      "Lists every model of the registry (shaders/brdf/models.cmake) with its lobes and parameters, as text or, "
      "with --json, as an array of {name, lobes, delta_only, params: [{name, type, min, max, default, scale, role, "
      "meaning}] (a file parameter: {name, type \"file\", role, meaning}, no range), sweep_base, presets: [{key, name, "
      "values}], glsl, reference} for scripts. docs/extending.md says how a model is added.",
      [json] { return listModels(*json); });
  addFlag(command, "--json", *json, "print JSON instead of text");
}

}  // namespace raylab
