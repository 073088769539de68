#include "brdf_params/material_params.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include "util/error.h"

namespace raylab {

namespace {

constexpr ParamInfo kRhoD{"rho_d", true, 0.0f, 1.0f, 0.5f, false, "diffuse reflectance"};
constexpr ParamInfo kRhoS{"rho_s", true, 0.0f, 1.0f, 0.5f, false, "specular reflectance"};
constexpr ParamInfo kS{"s", false, 1.0f, 10000.0f, 50.0f, true, "specular exponent"};
constexpr ParamInfo kM{"m", false, 0.001f, 1.0f, 0.2f, true, "Beckmann roughness (RMS slope)"};
constexpr ParamInfo kEta{"eta", false, 1.0f, 10.0f, 1.5f, false, "index of refraction, inside over outside"};
constexpr ParamInfo kAlphaX{"alpha_x", false, 0.001f, 1.0f, 0.2f, true, "roughness along the tangent"};
constexpr ParamInfo kAlphaY{"alpha_y", false, 0.001f, 1.0f, 0.2f, true, "roughness along the bitangent"};
constexpr ParamInfo kRd{"Rd", true, 0.0f, 1.0f, 0.5f, false, "diffuse reflectance"};
constexpr ParamInfo kRs{"Rs", true, 0.0f, 1.0f, 0.5f, false, "specular reflectance at normal incidence"};
constexpr ParamInfo kNu{"nu", false, 1.0f, 10000.0f, 100.0f, true, "exponent along the tangent"};
constexpr ParamInfo kNv{"nv", false, 1.0f, 10000.0f, 100.0f, true, "exponent along the bitangent"};
constexpr ParamInfo kTint{"tint", true, 0.0f, 1.0f, 1.0f, false, "transmittance colour"};
constexpr ParamInfo kDelta{"delta", false, 0.0f, 1.0f, 0.0f, false, "mirror-reflection weight"};

const std::vector<ModelInfo>& models() {
  static const std::vector<ModelInfo> table = {
      {"lambert", gpu::kModelLambert, {kRhoD}},
      {"phong", gpu::kModelPhong, {kRhoD, kRhoS, kS}},
      {"blinnphong", gpu::kModelBlinnPhong, {kRhoD, kRhoS, kS}},
      {"cooktorrance", gpu::kModelCookTorrance, {kRhoD, kRhoS, kM, kEta}},
      {"ward", gpu::kModelWard, {kRhoD, kRhoS, kAlphaX, kAlphaY}},
      {"ward_duer", gpu::kModelWardDuer, {kRhoD, kRhoS, kAlphaX, kAlphaY}},
      {"ward_gmd", gpu::kModelWardGmd, {kRhoD, kRhoS, kAlphaX, kAlphaY}},
      {"ashikhmin_shirley", gpu::kModelAshikhminShirley, {kRd, kRs, kNu, kNv}},
      {"glass", gpu::kModelGlass, {kEta, kTint}},
  };
  return table;
}

// Where each named parameter lives in the record. Rd and Rs share rhoD and rhoS (docs/brdfs.md).
glm::vec3* rgbSlot(gpu::MaterialRecord& r, std::string_view name) {
  if (name == "rho_d" || name == "Rd") return &r.rhoD;
  if (name == "rho_s" || name == "Rs") return &r.rhoS;
  if (name == "tint") return &r.tint;
  return nullptr;
}

float* scalarSlot(gpu::MaterialRecord& r, std::string_view name) {
  if (name == "s") return &r.s;
  if (name == "m") return &r.m;
  if (name == "eta") return &r.eta;
  if (name == "alpha_x") return &r.alphaX;
  if (name == "alpha_y") return &r.alphaY;
  if (name == "nu") return &r.nu;
  if (name == "nv") return &r.nv;
  if (name == "delta") return &r.delta;
  return nullptr;
}

std::string formatRange(const ParamInfo& p) {
  char text[64];
  std::snprintf(text, sizeof text, "[%g, %g]", p.min, p.max);
  return text;
}

}  // namespace

std::span<const ModelInfo> allModels() { return models(); }

const ModelInfo* findModel(std::string_view name) {
  for (const ModelInfo& model : models()) {
    if (model.name == name) return &model;
  }
  return nullptr;
}

const ModelInfo& modelInfo(std::uint32_t id) {
  for (const ModelInfo& model : models()) {
    if (model.id == id) return model;
  }
  throw Error("unknown model id " + std::to_string(id));
}

const ParamInfo& deltaParam() { return kDelta; }

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
  const int channels = param->rgb ? 3 : 1;
  for (int c = 0; c < channels; ++c) {
    if (!std::isfinite(value[c]) || value[c] < param->min || value[c] > param->max) {
      char shown[32];
      std::snprintf(shown, sizeof shown, "%g", value[c]);
      throw Error(where + ": " + std::string(name) + " = " + shown + " is outside " + formatRange(*param));
    }
  }
  if (param->rgb) *rgbSlot(record, name) = value;
  else *scalarSlot(record, name) = value.x;
}

glm::vec3 getParam(const gpu::MaterialRecord& record, std::string_view name) {
  gpu::MaterialRecord copy = record;
  if (glm::vec3* rgb = rgbSlot(copy, name)) return *rgb;
  if (float* scalar = scalarSlot(copy, name)) return glm::vec3(*scalar);
  throw Error("unknown parameter '" + std::string(name) + "'");
}

gpu::MaterialRecord defaultRecord(std::uint32_t model) {
  gpu::MaterialRecord record{};
  record.model = model;
  // Every slot gets a sane value, so that switching models in the viewer never reads garbage.
  for (const ModelInfo& m : models()) {
    for (const ParamInfo& p : m.params) {
      if (p.rgb) *rgbSlot(record, p.name) = glm::vec3(p.defaultValue);
      else *scalarSlot(record, p.name) = p.defaultValue;
    }
  }
  record.delta = kDelta.defaultValue;
  record.baseColorTexture = -1;
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
    text += " " + std::string(param.name) + "=" + formatParamValue(getParam(record, param.name), param.rgb);
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

void applyParamList(gpu::MaterialRecord& record, std::string_view text, const std::string& where) {
  std::set<std::string, std::less<>> seen;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find_first_of(",;", start), text.size());
    const std::string_view entry = trimmed(text.substr(start, end - start));
    start = end + 1;
    if (entry.empty()) continue;  // "" (all defaults) and a trailing separator
    const std::size_t equals = entry.find('=');
    if (equals == std::string_view::npos) {
      throw Error(where + ": expected name=value, got '" + std::string(entry) + "'");
    }
    const std::string name(trimmed(entry.substr(0, equals)));
    const std::string_view valueText = trimmed(entry.substr(equals + 1));
    const ParamInfo* param = findParam(modelInfo(record.model), name);
    if (param == nullptr) setParam(record, name, glm::vec3(0.0f), where);  // its message lists the parameters
    if (!seen.insert(name).second) throw Error(where + ": '" + name + "' is given twice");
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
