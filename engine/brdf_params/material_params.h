// The models and parameters by name: the table generated from the model registry (shaders/brdf/models.cmake)
// and the parameter table each model's GLSL file opens with (docs/extending.md). The CSV evaluator, glTF
// materials, the viewer's sliders, `raylab sweep`, `raylab brdf models` and Python all read it, so that names,
// ranges and defaults agree.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "shared/scene_records.h"

namespace raylab {

struct ParamInfo {
  std::string_view name;  // as in the contract: "rho_d", "alpha_x", ...
  bool rgb;               // an RGB triple, written r/g/b in the CSV
  float min;
  float max;
  float defaultValue;     // each channel for RGB parameters
  bool logScale;          // exponents and roughness: sliders and sweeps go geometrically
  std::string_view meaning;
  // What the parameter means across models, for switching a material's model (the viewer carries the
  // appearance over) and for textures (which multiply the `diffuse` one): diffuse, specular, eta, transmittance, slope,
  // slope_x, slope_y, exponent (Blinn's, of N.H), mirror_exponent (Phong's, of R.wo), exponent_x, exponent_y;
  // file (a measured model's data file: the slot holds its id in engine/measured/measured_library.h, set by
  // setFileParam from a path, never by a number); empty for none.
  std::string_view role;
  std::uint32_t slot;     // first float in MaterialRecord::params
};

// A named set of parameter values a model's file declares (`// preset: metal=Au eta=... k=...`): `key` = `name`
// in a parameter list, glTF's extras.raylab or Python sets them.
struct PresetValue {
  std::string_view param;
  glm::vec3 value;  // each channel; a scalar parameter's in x
};
struct Preset {
  std::string_view key;   // "metal"
  std::string_view name;  // "Au"
  std::vector<PresetValue> values;
};

// A part of a model a scene compiles only when one of its materials uses it (`// feature: coat coat_weight`):
// when `param` > 0. `bit` is its kSpecFeatures bit (shared/features.h), from 1 << 16 up.
struct ModelFeature {
  std::string_view name;   // "coat"
  std::string_view param;  // "coat_weight"
  std::uint32_t bit;
};

struct ModelInfo {
  std::string_view name;  // "cooktorrance"
  std::uint32_t id;       // the registry's order
  std::uint32_t lobes;    // gpu::kLobe... flags (shared/brdf_lobes.h)
  std::vector<ParamInfo> params;  // without delta, which every material has
  std::string_view sweepBase;     // a parameter list a sweep starts from (empty: the defaults)
  std::string_view glslFile;      // relative to the source tree
  std::string_view referenceFile;
  std::vector<Preset> presets;    // in the file's order
  // Why f(wi, wo) differs from f(wo, wi) (`// reciprocal: no, ...`), or empty: the model is reciprocal, and
  // brdf_reciprocity_test holds it to that.
  std::string_view nonReciprocal;
  // Why `raylab brdf fit` fits the model only when it is named (`// fit: by name, ...`), or empty: it is among the
  // models a fit tries by default.
  std::string_view fitByName;
  // Its Levenberg-Marquardt starts when a fit names no count (`// fit: starts N, ...`), or 0: FitOptions' default.
  std::uint32_t fitStarts;
  // How many times a fit's --search points its search draws (`// fit: search Nx, ...`), or 1.
  std::uint32_t fitSearchFactor;
  // One more start of a fit (`// fit: start NAME=VALUE ...`): the defaults with these values, every channel alike.
  std::vector<std::pair<std::string_view, double>> fitStart;
  // The parameters a fit frees (`// fit: free NAME ...`), the rest held at their defaults; empty: all it can.
  std::vector<std::string_view> fitFree;
  std::vector<ModelFeature> features;  // its `feature:` lines
};

// The registry's table (generated: brdf_model_table.cpp), in id order.
const std::vector<ModelInfo>& registeredModels();
std::span<const ModelInfo> allModels();
// "lambert, phong, ...": every model's name, for messages and help.
std::string modelNames();
// True for a model of delta lobes only (glass): no f, no density; the integrators follow its DeltaEvent.
bool isDeltaOnly(const ModelInfo& model);
bool isDeltaOnly(std::uint32_t model);
// Transmission with a density (rough glass): f and its sampler take wi and wo on either side of the normal.
bool isTwoSided(const ModelInfo& model);
// True when `key` names presets of `model` ("metal" for ggx_conductor).
bool isPresetKey(const ModelInfo& model, std::string_view key);
// Sets the values of preset `key` = `name`; an unknown name throws Error naming `where` and the known names.
void applyPreset(gpu::MaterialRecord& record, std::string_view key, std::string_view name, const std::string& where);
// The parameter of `model` with `role`, or null.
const ParamInfo* findRole(const ModelInfo& model, std::string_view role);
const ModelInfo* findModel(std::string_view name);
// The id of a model the code itself names (a built-in scene's, an importer's); throws Error when absent.
std::uint32_t modelId(std::string_view name);
const ModelInfo& modelInfo(std::uint32_t id);
// delta: the mirror-reflection weight every material carries.
const ParamInfo& deltaParam();
// The ParamInfo of `name` for `model` (delta included), or null.
const ParamInfo* findParam(const ModelInfo& model, std::string_view name);
// The layer of a parameter of a layered model, one whose parameters are all named LAYER_rest in layers of two or
// more (OpenPBR's naming: "coat" for coat_roughness, "thin_film" for thin_film_ior, a layer being the shortest
// prefix with a LAYER_weight); empty for every other model. The viewer groups by it.
std::string_view paramLayer(const ModelInfo& model, const ParamInfo& param);

// Sets one parameter of `record` (whose model is already set). Throws Error naming `where`, the parameter and
// the accepted range when the name is unknown for this model, the value is not finite or out of range.
// A file parameter takes only the id of a file already loaded (measured_library.h); paths go through setFileParam.
void setParam(gpu::MaterialRecord& record, std::string_view name, glm::vec3 value, const std::string& where);
// A model with its own emission (parameters of roles emission_luminance and emission_color: openpbr's) emits
// luminance x colour: setParam keeps record.emission, which the kernels and the light list read, equal to it.
bool hasOwnEmission(const ModelInfo& model);
// Sets record.emission, and for a model with its own emission its parameters to match (the luminance the largest
// channel, the colour the rest), so that the parameters stay the one source of it.
void setEmission(gpu::MaterialRecord& record, glm::vec3 radiance, const std::string& where);
// The coverage of a surface of this material (its parameter of role opacity: openpbr's geometry_opacity), 1 for a
// model without one. Below 1 a ray passes the surface with probability 1 - opacity (kernel/alpha.glsl).
float opacityOf(const gpu::MaterialRecord& record);
// Whether a material of this model can be partly transparent by its own parameters (it has a role opacity).
bool hasOpacity(const ModelInfo& model);
// The current value of a parameter (RGB parameters return three channels, scalars a splat).
glm::vec3 getParam(const gpu::MaterialRecord& record, std::string_view name);

// A parameter naming a data file (role `file`: measured's MERL file; role `network`: nbrdf's Keras file).
bool isFileParam(const ParamInfo& param);
// The model's file parameter, or null.
const ParamInfo* findFileParam(const ModelInfo& model);
// Loads the file at `path` (measured_library.h: once per process, every check of its reader) and points the
// parameter at it. Throws Error starting with `where` and naming the file.
void setFileParam(gpu::MaterialRecord& record, std::string_view name, const std::string& path, const std::string& where);
// The path a file parameter points at; empty when no file was given.
std::string fileParamPath(const gpu::MaterialRecord& record, const ParamInfo& param);
// Throws Error starting with `where` when a file parameter of the record's model has no file (a scene cannot
// render a measured material without its data).
void checkFileParams(const gpu::MaterialRecord& record, const std::string& where);

// The one grammar of a parameter list, on every command line, in CSV files and in Python strings: `k=v` entries
// separated by ',' or ';' (either; a CSV field uses ';' since ',' separates its columns), spaces around them
// ignored, RGB values as r/g/b (one number: grey). Sets each on `record` (whose model is set) with setParam's
// checks; a name given twice or a malformed value throws Error starting with `where`. A preset (`metal=Au`) is
// applied first, whatever its place in the list, so that the other entries refine it. A file parameter's value is
// a path, relative to `fileBase` unless absolute (the current directory when empty).
void applyParamList(gpu::MaterialRecord& record, std::string_view text, const std::string& where,
                    const std::string& fileBase = "");

// The colour a material shows at a glance (glTF viewers, a Lambert stand-in), in [0, 1]: its model's diffuse
// colour, else its specular colour, else its first RGB parameter ranging within [0, 1] (glass's tint), else grey.
glm::vec3 previewColour(const gpu::MaterialRecord& record);

// A record of `model` with every parameter at its default.
gpu::MaterialRecord defaultRecord(std::uint32_t model);

// A parameter's value as the command line writes it: "0.5", or "0.7/0.1/0.1" for an RGB value with unequal channels.
std::string formatParamValue(glm::vec3 value, bool rgb);
// "phong rho_d=0.7/0.1/0.1 rho_s=0.5 s=50": the model and its own parameters (not delta), in the syntax of
// `raylab brdf eval` and `--compare`.
std::string describeModelParams(const gpu::MaterialRecord& record);

}  // namespace raylab
