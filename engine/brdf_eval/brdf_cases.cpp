#include "brdf_eval/brdf_cases.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"
#include "util/error.h"

namespace raylab {

namespace {

constexpr std::array<std::string_view, 7> kColumns = {"id", "model", "params", "wi", "wo", "n", "t"};
constexpr std::string_view kHeader = "id,model,params,wi,wo,n,t";

std::string_view trim(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

std::vector<std::string_view> splitWhitespace(std::string_view text) {
  std::vector<std::string_view> parts;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) parts.push_back(text.substr(start, i - start));
  }
  return parts;
}

// A finite float32, written the way C and CSV writers write numbers ("-1.5e-7", "+2", ".5").
bool parseFloat(std::string_view text, float& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto [last, error] = std::from_chars(text.data(), end, value);
  return !text.empty() && error == std::errc() && last == end && std::isfinite(value);
}

std::string fieldWhere(const std::string& where, std::string_view field) {
  return where + ": field '" + std::string(field) + "'";
}

// A direction the kernel can normalise in float32: its squared length is a normal float, neither 0 nor
// overflowing.
glm::vec3 parseDirection(std::string_view text, const std::string& where) {
  const glm::vec3 v = parseVector(text, where);
  const double length2 = glm::dot(glm::dvec3(v), glm::dvec3(v));
  if (!(length2 >= 1e-36 && length2 <= 1e36)) {
    throw Error(where + ": expected a direction of length between 1e-18 and 1e18 (it is normalised), got '" +
                std::string(text) + "'");
  }
  return v;
}

BrdfCase parseRow(std::string_view line, int lineNumber, const std::string& source) {
  const std::string where = source + ":" + std::to_string(lineNumber);
  const std::vector<std::string_view> parts = split(line, ',');
  if (parts.size() != kColumns.size()) {
    throw Error(where + ": expected 7 fields (" + std::string(kHeader) + "), got " + std::to_string(parts.size()));
  }
  BrdfCase row;
  row.line = lineNumber;
  for (std::size_t i = 0; i < parts.size(); ++i) row.fields[i] = std::string(trim(parts[i]));
  const auto& [id, model, params, wi, wo, n, t] = row.fields;
  if (id.empty()) throw Error(fieldWhere(where, "id") + ": empty");

  // A file parameter (measured's file=) is relative to the CSV's folder.
  row.input.material =
      parseMaterial(model, params, where, std::filesystem::path(source).parent_path().string());
  // A delta BSDF (glass) is evaluated for the light direction alone: its two delta directions and Fresnel.
  const bool glass = isDeltaOnly(row.input.material.model);
  row.input.wi = parseDirection(wi, fieldWhere(where, "wi"));
  row.input.n = parseDirection(n, fieldWhere(where, "n"));
  for (const auto& [field, text] : {std::pair{"wo", &wo}, std::pair{"t", &t}}) {
    if (!glass && text->empty()) {
      throw Error(fieldWhere(where, field) + ": empty (only glass may leave wo and t empty)");
    }
  }
  row.input.wo = glass && wo.empty() ? glm::vec3(0.0f) : parseDirection(wo, fieldWhere(where, "wo"));
  // The tangent is only a hint: zero or parallel to n selects any tangent (shaders/common/frame.glsl).
  row.input.t = glass && t.empty() ? glm::vec3(0.0f) : parseVector(t, fieldWhere(where, "t"));
  return row;
}

std::string formatNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x + 0.0);  // + 0.0 turns -0 into 0
  return text;
}

std::string formatVector(const glm::dvec3& v) {
  return formatNumber(v.x) + " " + formatNumber(v.y) + " " + formatNumber(v.z);
}

// "r g b", or one number when the three channels print the same.
std::string formatRgb(const glm::dvec3& v) {
  const std::string r = formatNumber(v.x);
  if (formatNumber(v.y) == r && formatNumber(v.z) == r) return r;
  return formatVector(v);
}

}  // namespace

glm::vec3 parseVector(std::string_view text, const std::string& where) {
  const std::vector<std::string_view> numbers = splitWhitespace(trim(text));
  glm::vec3 v(0.0f);
  bool valid = numbers.size() == 3;
  for (std::size_t i = 0; valid && i < 3; ++i) valid = parseFloat(numbers[i], v[static_cast<int>(i)]);
  if (!valid) {
    throw Error(where + ": expected three finite numbers separated by spaces, got '" + std::string(text) + "'");
  }
  return v;
}

gpu::MaterialRecord parseMaterial(std::string_view model, std::string_view params, const std::string& where,
                                  const std::string& fileBase) {
  const ModelInfo* info = findModel(trim(model));
  if (info == nullptr) {
    throw Error(fieldWhere(where, "model") + ": unknown model '" + std::string(model) + "' (known: " + modelNames() +
                ")");
  }
  gpu::MaterialRecord record = defaultRecord(info->id);
  applyParamList(record, params, fieldWhere(where, "params"), fileBase);
  return record;
}

BrdfCaseFile parseBrdfCases(std::string_view text, const std::string& source) {
  BrdfCaseFile file;
  const MeasuredFileLimit measuredLimit(source);  // its rows are one batch on the device
  bool headerSeen = false;
  int lineNumber = 0;
  for (std::string_view line : split(text, '\n')) {
    ++lineNumber;
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    if (!headerSeen) {
      std::string header;
      for (std::string_view column : split(line, ',')) header += (header.empty() ? "" : ",") + std::string(trim(column));
      if (header != kHeader) {
        file.errors.push_back(source + ":" + std::to_string(lineNumber) + ": expected the header '" +
                              std::string(kHeader) + "', got '" + std::string(line) + "'");
        return file;
      }
      headerSeen = true;
      continue;
    }
    try {
      file.cases.push_back(parseRow(line, lineNumber, source));
    } catch (const Error& error) {
      file.errors.push_back(error.what());
    }
  }
  if (!headerSeen) file.errors.push_back(source + ": empty file, expected the header '" + std::string(kHeader) + "'");
  return file;
}

BrdfResult fromDevice(const gpu::BrdfEvalValue& value) {
  BrdfResult result;
  result.f = glm::dvec3(value.f);
  result.pdf = value.pdf;
  result.fresnelExact = value.fresnelExact;
  result.fresnelSchlick = value.fresnelSchlick;
  result.fresnelSchlickNaive = value.fresnelSchlickNaive;
  result.tir = value.tir != 0;
  result.reflected = glm::dvec3(value.reflected);
  result.refracted = glm::dvec3(value.refracted);
  return result;
}

std::string formatBrdfValues(std::span<const BrdfCase> cases, std::span<const BrdfResult> results) {
  std::string out = std::string(kHeader) + ",quantity,value\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string prefix;
    for (const std::string& field : cases[i].fields) prefix += field + ",";
    const BrdfResult& r = results[i];
    if (!isDeltaOnly(cases[i].input.material.model)) {
      out += prefix + "f," + formatRgb(r.f) + "\n";
      continue;
    }
    out += prefix + "F_exact," + formatNumber(r.fresnelExact) + "\n";
    out += prefix + "F_schlick," + formatNumber(r.fresnelSchlick) + "\n";
    out += prefix + "F_schlick_naive," + formatNumber(r.fresnelSchlickNaive) + "\n";
    out += prefix + "reflect," + formatVector(r.reflected) + "\n";
    out += prefix + "refract," + (r.tir ? std::string("none") : formatVector(r.refracted)) + "\n";
    out += prefix + "tir," + std::string(r.tir ? "1" : "0") + "\n";
  }
  return out;
}

}  // namespace raylab
