// What the fitting tests (brdf_fit_test, brdf_slice_fit_test) share: a scratch file per test program, and a
// material of the library from its parameter list.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "brdf_params/material_params.h"

namespace raylab::test {

// `name` in a folder of the temporary directory that belongs to `program` and this process.
inline std::string scratchFile(const std::string& program, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("raylab_" + program + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

inline gpu::MaterialRecord materialOf(const std::string& model, const std::string& params) {
  gpu::MaterialRecord record = defaultRecord(modelId(model));
  applyParamList(record, params, "test");
  return record;
}

}  // namespace raylab::test
