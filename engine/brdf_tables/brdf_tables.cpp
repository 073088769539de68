#include "brdf_tables/brdf_tables.h"

#include <span>

#include "generated/ggx_albedo.h"
#include "shared/brdf_tables.h"

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

Buffer createBrdfTables(const Device& device) {
  const std::vector<float> values = brdfTableValues();
  return createBufferWithData<float>(device, values, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "brdf tables");
}

}  // namespace raylab
