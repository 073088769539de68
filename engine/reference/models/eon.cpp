// EON (Portsmouth, Kutz & Hill, "EON: A practical energy-preserving rough diffuse BRDF", JCGT 14(1), 2025),
// exact-albedo variant: f = f_ss + f_ms (docs/brdfs.md, "eon"). G(mu) is written as the paper writes it, with
// acos and (S/mu)(1 - S^3); double precision keeps its cancellation near mu = 0 harmless down to mu ~ 1e-6.
#include <cmath>

#include "generated/reference_params.h"
#include "reference/terms.h"

namespace raylab::reference {
namespace {

const double kC1 = 0.5 - 2.0 / (3.0 * kPi);
const double kC2 = 2.0 / 3.0 - 28.0 / (15.0 * kPi);

double albedoSingle(double mu, double r) {
  const double A = 1.0 / (1.0 + kC1 * r);
  const double S = std::sqrt(1.0 - mu * mu);
  const double G = S * (std::acos(mu) - S * mu) + (2.0 / 3.0) * ((S / mu) * (1.0 - S * S * S) - S);
  return A + r * A / kPi * G;
}

}  // namespace

Lobes eonEval(const EonParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double r = p.r;
  const double A = 1.0 / (1.0 + kC1 * r);
  const double s = glm::dot(wi, wo) - wi.z * wo.z;
  const double sOverT = s > 0.0 ? s / std::max(wi.z, wo.z) : s;
  dvec3 f = p.rho_d * (A * (1.0 + r * sOverT) / kPi);
  if (r > 0.0) {
    const double eBar = A * (1.0 + kC2 * r);
    const dvec3 rhoMs = p.rho_d * p.rho_d * eBar / (dvec3(1.0) - p.rho_d * (1.0 - eBar));
    f += rhoMs * ((1.0 - albedoSingle(wo.z, r)) * (1.0 - albedoSingle(wi.z, r)) / ((1.0 - eBar) * kPi));
  }
  return {f, dvec3(0.0)};
}

}  // namespace raylab::reference
