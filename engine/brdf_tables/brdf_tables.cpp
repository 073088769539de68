#include "brdf_tables/brdf_tables.h"

#include <algorithm>
#include <bit>
#include <memory>
#include <string>

#include "brdf_params/material_params.h"
#include "generated/ggx_albedo.h"
#include "measured/measured_library.h"
#include "reference/fuzz.h"
#include "reference/thin_film.h"
#include "shared/brdf_tables.h"
#include "util/error.h"

namespace raylab {

static_assert(std::size(reference::kGgxAlbedoLoss) == gpu::kGgxAlbedoSize * gpu::kGgxAlbedoSize);
static_assert(std::size(reference::kGgxAverageLoss) == gpu::kGgxAlbedoSize);
static_assert(std::size(reference::kDielectricAlbedoLoss) == gpu::kDielectricAlbedoFloats);
static_assert(std::size(reference::kMirrorAverageLoss) == gpu::kGgxAlbedoSize);
static_assert(std::size(reference::kAverageFresnel) == gpu::kDielectricAlbedoEpsSize);

std::vector<float> brdfTableValues() {
  std::vector<float> values(gpu::kBrdfTableFloats);
  for (std::size_t i = 0; i < std::size(reference::kGgxAlbedoLoss); ++i) {
    values[gpu::kGgxAlbedoOffset + i] = static_cast<float>(reference::kGgxAlbedoLoss[i]);
  }
  for (std::size_t i = 0; i < std::size(reference::kGgxAverageLoss); ++i) {
    values[gpu::kGgxAlbedoAverageOffset + i] = static_cast<float>(reference::kGgxAverageLoss[i]);
  }
  for (std::size_t i = 0; i < std::size(reference::kDielectricAlbedoLoss); ++i) {
    values[gpu::kDielectricAlbedoOffset + i] = static_cast<float>(reference::kDielectricAlbedoLoss[i]);
  }
  for (std::size_t i = 0; i < std::size(reference::kMirrorAverageLoss); ++i) {
    values[gpu::kMirrorAverageLossOffset + i] = static_cast<float>(reference::kMirrorAverageLoss[i]);
  }
  for (std::size_t i = 0; i < std::size(reference::kAverageFresnel); ++i) {
    values[gpu::kAverageFresnelOffset + i] = static_cast<float>(reference::kAverageFresnel[i]);
  }
  const std::vector<double>& film = reference::thinFilmSpectrum();
  for (std::size_t i = 0; i < film.size(); ++i) values[gpu::kThinFilmOffset + i] = static_cast<float>(film[i]);
  std::copy(std::begin(reference::kFuzzLtcTable), std::end(reference::kFuzzLtcTable), values.begin() + gpu::kFuzzLtcOffset);
  return values;
}

DeviceMaterials deviceMaterials(std::span<const gpu::MaterialRecord> records, std::span<const std::string> names) {
  DeviceMaterials out;
  out.records.assign(records.begin(), records.end());
  for (std::size_t i = 0; i < out.records.size(); ++i) {
    gpu::MaterialRecord& record = out.records[i];
    for (const ParamInfo& param : modelInfo(record.model).params) {
      if (!isFileParam(param)) continue;
      const std::string where = "material " + (i < names.size() ? "'" + names[i] + "'" : std::to_string(i));
      checkFileParams(record, where);
      const auto id = static_cast<std::uint32_t>(record.params[param.slot]);
      checkFileKind(measuredFilePath(id), param.role, where);
      auto at = std::find(out.measuredFiles.begin(), out.measuredFiles.end(), id);
      if (at == out.measuredFiles.end()) at = out.measuredFiles.insert(out.measuredFiles.end(), id);
      record.params[param.slot] = float(at - out.measuredFiles.begin());
    }
  }
  return out;
}

Buffer createBrdfTables(const Device& device, std::span<const std::uint32_t> measuredFiles) {
  if (measuredFiles.size() > gpu::kMaxFileBlocks) {
    throw Error(std::to_string(measuredFiles.size()) + " measured and neural BRDF files in one scene; the BRDF tables "
                "hold at most " + std::to_string(gpu::kMaxFileBlocks));
  }
  std::vector<std::shared_ptr<const MeasuredFile>> files;
  std::uint64_t floats = gpu::kFileBlocksOffset;
  for (const std::uint32_t id : measuredFiles) {
    files.push_back(measuredFile(id));
    floats += (files.back()->network ? gpu::kNbrdfBlockFloats : gpu::kMeasuredBlockFloats) + 3;  // + alignment
  }
  const std::uint64_t bytes = floats * sizeof(float);
  const std::uint64_t limit = device.properties.limits.maxStorageBufferRange;
  if (bytes > limit) {
    throw Error(std::to_string(measuredFiles.size()) + " measured files need " + std::to_string(bytes >> 20) +
                " MiB of BRDF tables (17 MiB per MERL file); the device binds at most " + std::to_string(limit >> 20) +
                " MiB in one buffer (maxStorageBufferRange): use fewer measured files in one scene");
  }
  std::vector<float> values = brdfTableValues();
  values.resize(gpu::kFileBlocksOffset, 0.0f);
  values.reserve(floats);
  for (std::size_t b = 0; b < files.size(); ++b) {
    // Each block starts at a multiple of 4 floats (a network is read as vec4s). The directory holds its first
    // float as the bits of a uint (exact beyond float's 2^24 integers).
    values.resize((values.size() + 3) / 4 * 4, 0.0f);
    values[gpu::kFileDirectoryOffset + b] = std::bit_cast<float>(std::uint32_t(values.size()));
    const std::vector<float> block = measuredDeviceBlock(*files[b]);
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
