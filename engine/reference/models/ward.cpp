// Ward, "Measuring and Modeling Anisotropic Reflection", SIGGRAPH 1992:
//   f = rho_d/pi + rho_s exp(-e) / (4 pi ax ay sqrt(cos_i cos_o)).
// The exponent e and the sampler are the Ward lobe's (ward_lobe.h).
#include <cmath>

#include "generated/reference_params.h"
#include "reference/terms.h"
#include "ward_lobe.h"

namespace raylab::reference {

Lobes wardEval(const WardParams& p, const dvec3& wi, const dvec3& wo) {
  return wardFamilyEval(p.rho_d, p.rho_s, p.alpha_x, p.alpha_y, wi, wo, [&](double lobe, const dvec3&) {
    return lobe / (4.0 * kPi * p.alpha_x * p.alpha_y * std::sqrt(wi.z * wo.z));
  });
}

dvec3 wardSampleSpecular(const WardParams& p, const dvec3& wo, const dvec2& u) {
  return wardLobeSample(p.alpha_x, p.alpha_y, wo, u);
}

double wardPdfSpecular(const WardParams& p, const dvec3& wi, const dvec3& wo) {
  return wardLobePdf(p.alpha_x, p.alpha_y, wi, wo);
}

SpecularLobe wardSpecularLobe(const WardParams& p) { return wardSpecularLobe(p.rho_d, p.rho_s, p.alpha_x, p.alpha_y); }

}  // namespace raylab::reference
