// Materials for the tests every model gets (sampling chi2 on the CPU and the device, albedo quadrature,
// reciprocity): each test keeps its hand-picked materials for the models it knows, and every registered model it
// does not name gets two generic ones from its parameter table, so that a newly registered model (a test-tree
// model included) is covered without an edit to the test (docs/extending.md).
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdf_params/material_params.h"
#include "support/measured_files.h"

namespace raylab::test {

struct GenericMaterial {
  std::string model;
  std::vector<std::pair<std::string_view, double>> params;  // every channel of an RGB parameter
};

// For each registered model with an f (not a delta BSDF) that `covered` lacks: its defaults with the diffuse
// colour 0.4 and its other colours 0.6, and with the diffuse colour 0 and the other colours 1 (the lobes alone); a
// file parameter (measured) points at the first test file in the one and the second in the other.
inline std::vector<GenericMaterial> uncoveredModelMaterials(const std::set<std::string, std::less<>>& covered) {
  std::vector<GenericMaterial> materials;
  for (const ModelInfo& model : allModels()) {
    if (isDeltaOnly(model) || covered.count(model.name) > 0) continue;
    int variant = 0;
    for (const auto& [diffuse, other] : {std::pair{0.4, 0.6}, std::pair{0.0, 1.0}}) {
      GenericMaterial material{std::string(model.name), {}};
      for (const ParamInfo& p : model.params) {
        if (p.rgb) material.params.push_back({p.name, p.role == "diffuse" ? diffuse : other});
        if (isFileParam(p)) material.params.push_back({p.name, double(testFileFor(p, variant))});
      }
      ++variant;
      materials.push_back(material);
    }
  }
  return materials;
}

// The viewer's polar angles (degrees from the normal) a sampling test draws from: normal, oblique and grazing, and
// for a two-sided model (rough glass) from inside too: 120 deg (beyond the critical angle of many microfacets) and
// 160 deg.
inline std::vector<double> samplingAngles(std::string_view model) {
  const ModelInfo* info = findModel(model);
  if (info != nullptr && isTwoSided(*info)) return {0.0, 45.0, 85.0, 120.0, 160.0};
  return {0.0, 45.0, 85.0};
}

}  // namespace raylab::test
