#include "brdf_params/material_params.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <stdexcept>

#include "measured/measured_library.h"
#include "shared/brdf_lobes.h"
#include "util/error.h"
#include "util/files.h"
#include "util/number_text.h"

namespace raylab {

namespace {

constexpr ParamInfo kDelta{"delta", false, 0.0f, 1.0f, 0.0f, false, "mirror-reflection weight", "", gpu::kNoParam};

glm::vec3 readSlot(const gpu::MaterialRecord& r, const ParamInfo& p) {
  if (p.rgb) return {r.params[p.slot], r.params[p.slot + 1], r.params[p.slot + 2]};
  return glm::vec3(r.params[p.slot]);
}

void writeSlot(gpu::MaterialRecord& r, const ParamInfo& p, glm::vec3 value) {
  r.params[p.slot] = value.x;
  if (p.rgb) {
    r.params[p.slot + 1] = value.y;
    r.params[p.slot + 2] = value.z;
  }
}

std::string formatRange(const ParamInfo& p) { return "[" + numberText(p.min) + ", " + numberText(p.max) + "]"; }

}  // namespace

std::span<const ModelInfo> allModels() {
  // The models of the test tree (tests/models/models.cmake) are registered in every build that builds the tests,
  // the README's release build included; a user never sees them: they exist only where RAYLAB_TEST_MODELS=1 (the
  // tests set it). They are registered after the library's models, so the library's are a prefix of the table.
  static const std::span<const ModelInfo> visible = [] {
    const std::vector<ModelInfo>& all = registeredModels();
    const char* flag = std::getenv("RAYLAB_TEST_MODELS");
    if (flag != nullptr && std::string_view(flag) == "1") return std::span<const ModelInfo>(all);
    std::size_t library = 0;
    while (library < all.size() && !all[library].glslFile.starts_with("tests/")) ++library;
    for (std::size_t i = library; i < all.size(); ++i) {
      if (!all[i].glslFile.starts_with("tests/")) throw std::logic_error("a library model registered after a test model");
    }
    return std::span<const ModelInfo>(all).first(library);
  }();
  return visible;
}

std::string modelNames() {
  std::string names;
  for (const ModelInfo& model : allModels()) names += (names.empty() ? "" : ", ") + std::string(model.name);
  return names;
}

bool isDeltaOnly(const ModelInfo& model) {
  return (model.lobes & gpu::kLobeSpecular) != 0 && (model.lobes & (gpu::kLobeDiffuse | gpu::kLobeGlossy)) == 0;
}

bool isDeltaOnly(std::uint32_t model) { return isDeltaOnly(modelInfo(model)); }

bool isTwoSided(const ModelInfo& model) {
  return (model.lobes & gpu::kLobeTransmission) != 0 && (model.lobes & (gpu::kLobeDiffuse | gpu::kLobeGlossy)) != 0;
}

bool isPresetKey(const ModelInfo& model, std::string_view key) {
  return std::any_of(model.presets.begin(), model.presets.end(), [&](const Preset& p) { return p.key == key; });
}

void applyPreset(gpu::MaterialRecord& record, std::string_view key, std::string_view name, const std::string& where) {
  const ModelInfo& model = modelInfo(record.model);
  std::string names;
  for (const Preset& preset : model.presets) {
    if (preset.key != key) continue;
    if (preset.name == name) {
      for (const PresetValue& v : preset.values) setParam(record, v.param, v.value, where);
      return;
    }
    names += (names.empty() ? "" : ", ") + std::string(preset.name);
  }
  throw Error(where + ": " + std::string(key) + " '" + std::string(name) + "' is not one of " + std::string(model.name) +
              "'s (" + (names.empty() ? std::string("it has none") : names) + ")");
}

const ParamInfo* findRole(const ModelInfo& model, std::string_view role) {
  for (const ParamInfo& param : model.params) {
    if (param.role == role) return &param;
  }
  return nullptr;
}

const ModelInfo* findModel(std::string_view name) {
  for (const ModelInfo& model : allModels()) {
    if (model.name == name) return &model;
  }
  return nullptr;
}

std::uint32_t modelId(std::string_view name) {
  const ModelInfo* model = findModel(name);
  if (model == nullptr) throw Error("model '" + std::string(name) + "' is not registered (the models are " + modelNames() + ")");
  return model->id;
}

const ModelInfo& modelInfo(std::uint32_t id) {
  if (id < allModels().size()) return allModels()[id];
  throw Error("unknown model id " + std::to_string(id));
}

const ParamInfo& deltaParam() { return kDelta; }

namespace {

std::string_view firstWord(std::string_view name) {
  const std::size_t underscore = name.find('_');
  return underscore == std::string_view::npos ? std::string_view() : name.substr(0, underscore);
}

// A parameter's layer: the shortest prefix of whole words that has a LAYER_weight in the model (OpenPBR gives each
// layer a weight: "thin_film" for thin_film_ior), else its first word.
std::string_view layerOf(const ModelInfo& model, std::string_view name) {
  for (std::size_t underscore = name.find('_'); underscore != std::string_view::npos;
       underscore = name.find('_', underscore + 1)) {
    const std::string weight = std::string(name.substr(0, underscore)) + "_weight";
    for (const ParamInfo& param : model.params) {
      if (param.name == weight) return name.substr(0, underscore);
    }
  }
  return firstWord(name);
}

// Three layers of two parameters at least: Ward's rho_d, rho_s, alpha_x, alpha_y are pairs, not layers.
bool isLayered(const ModelInfo& model) {
  std::vector<std::string_view> layers;
  for (const ParamInfo& param : model.params) {
    const std::string_view layer = layerOf(model, param.name);
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) layers.push_back(layer);
  }
  int groups = 0;  // layers of two or more parameters (a lone parameter may have its own: geometry_thin_walled)
  for (const std::string_view layer : layers) {
    if (layer.empty()) return false;
    int members = 0;
    for (const ParamInfo& other : model.params) members += layerOf(model, other.name) == layer ? 1 : 0;
    groups += members >= 2 ? 1 : 0;
  }
  return groups >= 3;
}

}  // namespace

std::string_view paramLayer(const ModelInfo& model, const ParamInfo& param) {
  return isLayered(model) ? layerOf(model, param.name) : std::string_view();
}

const ParamInfo* findParam(const ModelInfo& model, std::string_view name) {
  if (name == kDelta.name) return &kDelta;
  for (const ParamInfo& param : model.params) {
    if (param.name == name) return &param;
  }
  return nullptr;
}

void setParam(gpu::MaterialRecord& record, std::string_view name, glm::vec3 value, const std::string& where) {
  const ModelInfo& model = modelInfo(record.model);
  const ParamInfo* param = findParam(model, name);
  if (param == nullptr) {
    std::string known;
    for (const ParamInfo& p : model.params) known += std::string(p.name) + ", ";
    known += "delta";
    throw Error(where + ": '" + std::string(name) + "' is not a parameter of " + std::string(model.name) +
                " (it has " + known + ")");
  }
  if (isFileParam(*param)) {
    // A number names a file only as the id of one already loaded (measured_library.h), as a copy of a record
    // holds it; a user gives a path (setFileParam).
    const auto id = static_cast<std::uint32_t>(value.x);
    bool loaded = value.x == float(id) && id != kNoMeasuredFile;
    std::string path;
    if (loaded) {
      try {
        path = measuredFilePath(id);
      } catch (const Error&) {
        loaded = false;
      }
    }
    if (loaded) checkFileKind(path, param->role, where + ": " + std::string(name));
    if (!loaded) {
      throw Error(where + ": " + std::string(name) + " of " + std::string(model.name) + " is a file: give its path (" +
                  std::string(name) + "=PATH)");
    }
    record.params[param->slot] = value.x;
    return;
  }
  const int channels = param->rgb ? 3 : 1;
  for (int c = 0; c < channels; ++c) {
    if (!std::isfinite(value[c]) || value[c] < param->min || value[c] > param->max) {
      // A value outside its range is a usage error wherever it comes from (a scene's material, --material, a
      // script): exit 2, as for the command line.
      throw Error(where + ": " + std::string(name) + " = " + numberText(value[c]) + " is outside " +
                  formatRange(*param), kExitUsage);
    }
  }
  if (param == &kDelta) record.delta = value.x;
  else writeSlot(record, *param, value);
  if (param->role == "emission_luminance" || param->role == "emission_color") {
    const ParamInfo& luminance = *findRole(model, "emission_luminance");
    const ParamInfo& colour = *findRole(model, "emission_color");
    record.emission = readSlot(record, luminance).x * readSlot(record, colour);
  }
}

bool hasOwnEmission(const ModelInfo& model) {
  return findRole(model, "emission_luminance") != nullptr && findRole(model, "emission_color") != nullptr;
}

void setEmission(gpu::MaterialRecord& record, glm::vec3 radiance, const std::string& where) {
  const ModelInfo& model = modelInfo(record.model);
  if (!hasOwnEmission(model)) {
    record.emission = radiance;
    return;
  }
  const float luminance = std::max({radiance.x, radiance.y, radiance.z, 0.0f});
  const ParamInfo& colour = *findRole(model, "emission_color");
  if (luminance > 0.0f) setParam(record, colour.name, glm::clamp(radiance / luminance, 0.0f, 1.0f), where);
  setParam(record, findRole(model, "emission_luminance")->name, glm::vec3(luminance), where);
}

bool hasOpacity(const ModelInfo& model) { return findRole(model, "opacity") != nullptr; }

float opacityOf(const gpu::MaterialRecord& record) {
  const ParamInfo* opacity = findRole(modelInfo(record.model), "opacity");
  return opacity == nullptr ? 1.0f : readSlot(record, *opacity).x;
}

glm::vec3 getParam(const gpu::MaterialRecord& record, std::string_view name) {
  const ParamInfo* param = findParam(modelInfo(record.model), name);
  if (param == nullptr) {
    throw Error("'" + std::string(name) + "' is not a parameter of " + std::string(modelInfo(record.model).name));
  }
  return param == &kDelta ? glm::vec3(record.delta) : readSlot(record, *param);
}

bool isFileParam(const ParamInfo& param) { return param.role == "file" || param.role == "network"; }

const ParamInfo* findFileParam(const ModelInfo& model) {
  for (const ParamInfo& param : model.params) {
    if (isFileParam(param)) return &param;
  }
  return nullptr;
}

void setFileParam(gpu::MaterialRecord& record, std::string_view name, const std::string& path, const std::string& where) {
  const ParamInfo* param = findParam(modelInfo(record.model), name);
  if (param == nullptr || !isFileParam(*param)) {
    throw Error(where + ": '" + std::string(name) + "' is not a file parameter of " +
                std::string(modelInfo(record.model).name));
  }
  if (path.empty()) throw Error(where + ": " + std::string(name) + " is empty; expected the path of a file");
  std::uint32_t id = kNoMeasuredFile;
  try {
    checkFileKind(path, param->role, where + ": " + std::string(name));
    id = loadMeasured(path);
  } catch (const FileError& error) {
    throw FileError(where + ": " + std::string(name) + ": " + error.what(), error.problem());
  } catch (const Error& error) {
    throw Error(where + ": " + std::string(name) + ": " + error.what());
  }
  record.params[param->slot] = float(id);
}

std::string fileParamPath(const gpu::MaterialRecord& record, const ParamInfo& param) {
  const auto id = static_cast<std::uint32_t>(record.params[param.slot]);
  return id == kNoMeasuredFile ? std::string() : measuredFilePath(id);
}

void checkFileParams(const gpu::MaterialRecord& record, const std::string& where) {
  for (const ParamInfo& param : modelInfo(record.model).params) {
    if (isFileParam(param) && fileParamPath(record, param).empty()) {
      throw Error(where + ": " + std::string(modelInfo(record.model).name) + " needs its " + std::string(param.name) +
                  " (" + std::string(param.name) + "=PATH of " + fileKindText(param.role) + ")");
    }
  }
}

glm::vec3 previewColour(const gpu::MaterialRecord& record) {
  const ModelInfo& model = modelInfo(record.model);
  // A colour in [0, 1]: the diffuse colour, else the specular one, else the first RGB parameter that is a colour
  // (not an index of refraction like a conductor's eta, which glTF's baseColorFactor could not hold).
  const auto colour = [&](const ParamInfo& param) { return glm::clamp(getParam(record, param.name), 0.0f, 1.0f); };
  if (const ParamInfo* diffuse = findRole(model, "diffuse"); diffuse && diffuse->rgb) return colour(*diffuse);
  if (const ParamInfo* specular = findRole(model, "specular"); specular && specular->rgb) return colour(*specular);
  for (const ParamInfo& param : model.params) {
    if (param.rgb && param.min >= 0.0f && param.max <= 1.0f) return colour(param);
  }
  return glm::vec3(0.5f);
}

gpu::MaterialRecord defaultRecord(std::uint32_t model) {
  const ModelInfo& info = modelInfo(model);
  gpu::MaterialRecord record{};
  record.model = model;
  for (const ParamInfo& p : info.params) writeSlot(record, p, glm::vec3(p.defaultValue));
  const ParamInfo* diffuse = findRole(info, "diffuse");
  record.diffuseParam = diffuse != nullptr && diffuse->rgb ? diffuse->slot : gpu::kNoParam;
  record.delta = kDelta.defaultValue;
  record.textures = -1;
  // The slots textures scale, by role: a scalar's, and specular_tint's first of three.
  const auto slotOf = [&](const char* role, bool rgb) {
    const ParamInfo* param = findRole(info, role);
    return param != nullptr && param->rgb == rgb ? param->slot : gpu::kNoTextureParam;
  };
  record.textureParams = slotOf("roughness", false) | (slotOf("metallic", false) << 8u) |
                         (slotOf("specular_weight", false) << 16u) | (slotOf("specular_tint", true) << 24u);
  return record;
}

std::string formatParamValue(glm::vec3 value, bool rgb) {
  char text[96];
  if (rgb && !(value.x == value.y && value.y == value.z)) {
    std::snprintf(text, sizeof text, "%g/%g/%g", double(value.x), double(value.y), double(value.z));
  } else {
    std::snprintf(text, sizeof text, "%g", double(value.x));
  }
  return text;
}

std::string describeModelParams(const gpu::MaterialRecord& record) {
  const ModelInfo& model = modelInfo(record.model);
  std::string text(model.name);
  for (const ParamInfo& param : model.params) {
    text += " " + std::string(param.name) + "=" +
            (isFileParam(param) ? fileParamPath(record, param) : formatParamValue(getParam(record, param.name), param.rgb));
  }
  return text;
}

namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

bool parseNumber(std::string_view text, float& value) {
  text = trimmed(text);
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

}  // namespace

void applyParamList(gpu::MaterialRecord& record, std::string_view text, const std::string& where,
                    const std::string& fileBase) {
  const ModelInfo& model = modelInfo(record.model);
  std::set<std::string, std::less<>> seen;
  std::vector<std::pair<std::string, std::string_view>> numbers;  // after the presets, which they refine
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find_first_of(",;", start), text.size());
    const std::string_view entry = trimmed(text.substr(start, end - start));
    start = end + 1;
    if (entry.empty()) continue;  // "" (all defaults) and a trailing separator
    const std::size_t equals = entry.find('=');
    if (equals == std::string_view::npos) {
      // ',' and ';' separate the entries, so a file's path cannot hold them: say so where that is the likely cause.
      const bool afterFile = !numbers.empty() && isFileParam(*findParam(model, numbers.back().first));
      throw Error(where + ": expected name=value, got '" + std::string(entry) + "'" +
                  (afterFile ? " (a path given as file=... cannot contain ',' or ';', which separate the parameters: "
                               "rename the file or link it under a name without them)"
                             : ""));
    }
    const std::string name(trimmed(entry.substr(0, equals)));
    const std::string_view valueText = trimmed(entry.substr(equals + 1));
    const bool preset = isPresetKey(model, name);
    if (!preset && findParam(model, name) == nullptr) {
      setParam(record, name, glm::vec3(0.0f), where);  // its message lists the parameters
    }
    if (!seen.insert(name).second) throw Error(where + ": '" + name + "' is given twice");
    if (preset) {
      applyPreset(record, name, valueText, where);
    } else {
      numbers.emplace_back(name, valueText);
    }
  }
  for (const auto& [name, valueText] : numbers) {
    const ParamInfo* param = findParam(model, name);
    if (isFileParam(*param)) {
      const std::filesystem::path path{std::string(valueText)};
      setFileParam(record, name,
                   path.is_absolute() || fileBase.empty() || valueText.empty() ? path.string()
                                                                               : (std::filesystem::path(fileBase) / path).string(),
                   where);
      continue;
    }
    glm::vec3 value(0.0f);
    int channels = 0;
    bool valid = true;
    for (std::size_t from = 0; valid && from <= valueText.size(); ++channels) {
      const std::size_t slash = std::min(valueText.find('/', from), valueText.size());
      valid = channels < 3 && parseNumber(valueText.substr(from, slash - from), value[channels]);
      from = slash + 1;
    }
    if (!valid || !(channels == 1 || (channels == 3 && param->rgb))) {
      const std::string expected = param->rgb ? "a number or r/g/b" : "a number";
      throw Error(where + ": " + name + ": expected " + expected + ", got '" + std::string(valueText) + "'");
    }
    if (channels == 1) value = glm::vec3(value.x);  // a grey RGB value
    setParam(record, name, value, where);  // out-of-range values: the message names the range
  }
}

}  // namespace raylab
