// MERL files for the tests, made by the project's own writer from known models of the library (the database may not
// be redistributed): written once per process to a scratch folder and loaded, so that a test holds the file's id
// (measured_library.h) as a material's `file` parameter.
#pragma once

#include <cstdint>
#include <string>

#include "brdf_params/material_params.h"

namespace raylab::test {

struct MeasuredTestFile {
  const char* name;         // the file's name in the scratch folder
  const char* model;        // the model it tabulates
  const char* params;       // and its parameters, as a parameter list
};

// 0: cooktorrance rho_d=0.2 rho_s=0.8 m=0.3 (a Beckmann lobe over a diffuse floor);
// 1: gltf_pbr base_color=0.9/0.6/0.3 metallic=1 roughness=0.25 (a coloured GGX metal, no diffuse term).
inline constexpr MeasuredTestFile kMeasuredTestFiles[] = {
    {"cooktorrance.binary", "cooktorrance", "rho_d=0.2, rho_s=0.8, m=0.3"},
    {"gold_ggx.binary", "gltf_pbr", "base_color=0.9/0.6/0.3, metallic=1, roughness=0.25"},
};

// The path of test file `which`, written on first use.
std::string measuredTestPath(int which);
// Its id, loaded on first use.
std::uint32_t measuredTestFile(int which);
// The id of test file `which` (0 or 1) of the kind the file parameter `param` takes: a MERL file above, or a
// neural BRDF (nbrdf_files.h).
std::uint32_t testFileFor(const ParamInfo& param, int which);

}  // namespace raylab::test
