// The CSV files of `raylab brdf eval` (docs/brdf_contract.md, "raylab brdf eval CSV"): cases in, values out.
//   in:  id,model,params,wi,wo,n,t       params "k=v;k=v" (RGB "r/g/b"), vectors "x y z"; glass may leave wo, t empty
//   out: id,model,params,wi,wo,n,t,quantity,value
// Parameters a row does not name take the defaults of engine/brdf_params/material_params.cpp; a single number sets
// all three channels of an RGB parameter. Numbers are read as float32, the precision of the device: both
// backends evaluate exactly those values. Blank lines and lines starting with # are skipped.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shared/brdf_eval.h"

namespace raylab {

struct BrdfCase {
  int line = 0;                       // 1-based line of the input file
  std::array<std::string, 7> fields;  // id, model, params, wi, wo, n, t as written (trimmed), echoed in the output
  gpu::BrdfEvalCase input;            // what the evaluators read
};

struct BrdfCaseFile {
  std::vector<BrdfCase> cases;      // the well-formed rows, in file order
  std::vector<std::string> errors;  // one per malformed row: "<source>:<line>: <field>: <what is wrong>"
};

// Parses a cases file; `source` names it in the errors. A malformed header is an error of its own and no
// row is read; a malformed row is reported and skipped, the others are kept.
BrdfCaseFile parseBrdfCases(std::string_view text, const std::string& source);

// A material from a model name and a "k=v;k=v" list; unspecified parameters keep their defaults. Throws
// Error naming `where`, the field and what was expected.
// The backend every BRDF command and call takes unless told otherwise (`raylab brdf eval|albedo`, raylab.brdf): the
// device, whose shaders render; `cpu` is the double-precision reference to compare against.
inline constexpr const char* kDefaultBrdfBackend = "gpu";

// A file parameter's path is relative to `fileBase` (the current directory when empty).
gpu::MaterialRecord parseMaterial(std::string_view model, std::string_view params, const std::string& where,
                                  const std::string& fileBase = "");

// "x y z": three finite numbers separated by spaces. Throws Error naming `where`.
glm::vec3 parseVector(std::string_view text, const std::string& where);

// One case's values in double: the cpu backend's exactly, the device's promoted from float.
struct BrdfResult {
  glm::dvec3 f{0.0};  // BRDF models
  double pdf = 0.0;   // BRDF models: the sampler's density of wi given wo (not written to the CSV)
  double fresnelExact = 0.0;
  double fresnelSchlick = 0.0;
  double fresnelSchlickNaive = 0.0;
  bool tir = false;
  glm::dvec3 reflected{0.0};
  glm::dvec3 refracted{0.0};  // zero under total internal reflection
};

BrdfResult fromDevice(const gpu::BrdfEvalValue& value);

// The output file: a header, then one row per BRDF case (quantity f) and six per glass case (F_exact,
// F_schlick, F_schlick_naive, reflect, refract, tir), numbers with 9 significant digits.
std::string formatBrdfValues(std::span<const BrdfCase> cases, std::span<const BrdfResult> results);

}  // namespace raylab
