#include "reference/brdf_reference.h"

namespace raylab::reference {

Material fromRecord(const gpu::MaterialRecord& record) {
  Material material;
  material.model = record.model;
  material.delta = record.delta;
  for (std::size_t i = 0; i < material.params.size(); ++i) material.params[i] = record.params[i];
  return material;
}

}  // namespace raylab::reference
