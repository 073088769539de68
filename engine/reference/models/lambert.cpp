// Lambert, "Photometria", 1760 (docs/brdf_contract.md, "Formulas"): f = rho_d / pi.
#include "generated/reference_params.h"
#include "reference/terms.h"

namespace raylab::reference {

Lobes lambertEval(const LambertParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {p.rho_d * kInvPi, dvec3(0.0)};
}

}  // namespace raylab::reference
