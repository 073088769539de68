#include "support/measured_files.h"

#include <filesystem>
#include <unistd.h>

#include <mutex>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "support/nbrdf_files.h"

namespace raylab::test {

std::string measuredTestPath(int which) {
  static std::mutex mutex;
  static std::string paths[std::size(kMeasuredTestFiles)];
  const std::lock_guard lock(mutex);
  std::string& path = paths[which];
  if (path.empty()) {
    const MeasuredTestFile& file = kMeasuredTestFiles[which];
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raylab_measured_test_files";
    std::filesystem::create_directories(dir);
    gpu::MaterialRecord record = defaultRecord(modelId(file.model));
    applyParamList(record, file.params, std::string("test file ") + file.name);
    const reference::Material material = reference::fromRecord(record);
    // Per process: parallel test processes never write the same path.
    path = (dir / (std::to_string(::getpid()) + "_" + file.name)).string();
    writeMerl(path, tabulateMerl([&](const glm::dvec3& wi, const glm::dvec3& wo) { return reference::eval(material, wi, wo); }));
  }
  return path;
}

std::uint32_t measuredTestFile(int which) { return loadMeasured(measuredTestPath(which)); }

std::uint32_t testFileFor(const ParamInfo& param, int which) {
  return param.role == std::string_view("network") ? nbrdfTestFile(which) : measuredTestFile(which);
}

}  // namespace raylab::test
