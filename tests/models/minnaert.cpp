// The double-precision reference of the test-tree model minnaert (minnaert.glsl):
// f = rho_d (k+1)/(2 pi) (cos_i cos_o)^(k-1), a diffuse term only.
#include <cmath>

#include "generated/reference_params.h"
#include "reference/terms.h"

namespace raylab::reference {

Lobes minnaertEval(const MinnaertParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {p.rho_d * ((p.k + 1.0) / (2.0 * kPi) * std::pow(wi.z * wo.z, p.k - 1.0)), dvec3(0.0)};
}

}  // namespace raylab::reference
