#include "brdf_tables/brdf_tables.h"

#include <algorithm>
#include <string>

#include "brdf_params/material_params.h"
#include "generated/ggx_albedo.h"
#include "measured/measured_library.h"
#include "shared/brdf_tables.h"
#include "util/error.h"

namespace raylab {

static_assert(std::size(reference::kGgxAlbedoLoss) == gpu::kGgxAlbedoSize * gpu::kGgxAlbedoSize);
static_assert(std::size(reference::kGgxAverageLoss) == gpu::kGgxAlbedoSize);

std::vector<float> brdfTableValues() {
  std::vector<float> values(gpu::kBrdfTableFloats);
  for (std::size_t i = 0; i < std::size(reference::kGgxAlbedoLoss); ++i) {
    values[gpu::kGgxAlbedoOffset + i] = static_cast<float>(reference::kGgxAlbedoLoss[i]);
  }
  for (std::size_t i = 0; i < std::size(reference::kGgxAverageLoss); ++i) {
    values[gpu::kGgxAlbedoAverageOffset + i] = static_cast<float>(reference::kGgxAverageLoss[i]);
  }
  return values;
}

DeviceMaterials deviceMaterials(std::span<const gpu::MaterialRecord> records, std::span<const std::string> names) {
  DeviceMaterials out;
  out.records.assign(records.begin(), records.end());
  for (std::size_t i = 0; i < out.records.size(); ++i) {
    gpu::MaterialRecord& record = out.records[i];
    for (const ParamInfo& param : modelInfo(record.model).params) {
      if (!isFileParam(param)) continue;
      checkFileParams(record, "material " + (i < names.size() ? "'" + names[i] + "'" : std::to_string(i)));
      const auto id = static_cast<std::uint32_t>(record.params[param.slot]);
      auto at = std::find(out.measuredFiles.begin(), out.measuredFiles.end(), id);
      if (at == out.measuredFiles.end()) at = out.measuredFiles.insert(out.measuredFiles.end(), id);
      record.params[param.slot] = float(at - out.measuredFiles.begin());
    }
  }
  return out;
}

Buffer createBrdfTables(const Device& device, std::span<const std::uint32_t> measuredFiles) {
  std::vector<float> values = brdfTableValues();
  const std::uint64_t bytes =
      (std::uint64_t(gpu::kMeasuredOffset) + std::uint64_t(gpu::kMeasuredBlockFloats) * measuredFiles.size()) * sizeof(float);
  const std::uint64_t limit = device.properties.limits.maxStorageBufferRange;
  if (bytes > limit) {
    throw Error(std::to_string(measuredFiles.size()) + " measured files need " + std::to_string(bytes >> 20) +
                " MiB of BRDF tables (17 MiB each); the device binds at most " + std::to_string(limit >> 20) +
                " MiB in one buffer (maxStorageBufferRange): use fewer measured files in one scene");
  }
  values.resize(gpu::kMeasuredOffset, 0.0f);
  for (const std::uint32_t id : measuredFiles) {
    const std::vector<float> block = measuredDeviceBlock(*measuredFile(id));
    values.insert(values.end(), block.begin(), block.end());
  }
  return createBufferWithData<float>(device, values, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "brdf tables");
}

bool updateBrdfTables(const Device& device, Buffer& tables, std::vector<std::uint32_t>& current,
                      std::span<const std::uint32_t> wanted) {
  if (tables.handle != VK_NULL_HANDLE && std::equal(current.begin(), current.end(), wanted.begin(), wanted.end())) {
    return false;
  }
  Buffer replacement = createBrdfTables(device, wanted);
  destroyBuffer(device, tables);
  tables = replacement;
  current.assign(wanted.begin(), wanted.end());
  return true;
}

}  // namespace raylab
