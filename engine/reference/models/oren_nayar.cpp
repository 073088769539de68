// Oren & Nayar, "Generalization of Lambert's Reflectance Model", SIGGRAPH 1994, qualitative model (pbrt-v3's
// OrenNayar), as the paper writes it: f = rho_d/pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
// alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o), with the sines, cosines and tangent of those
// angles taken from the directions' components (tan(atan2(...)) near pi/2 would lose everything to the rounding
// of pi/2). The GLSL writes the whole product as one quotient of dot products; the two are independent.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/terms.h"

namespace raylab::reference {

Lobes orenNayarEval(const OrenNayarParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double sigma2 = p.sigma * p.sigma;
  const double A = 1.0 - sigma2 / (2.0 * (sigma2 + 0.33));
  const double B = 0.45 * sigma2 / (sigma2 + 0.09);
  const double sinI = std::hypot(wi.x, wi.y), sinO = std::hypot(wo.x, wo.y);
  // alpha is the angle of the direction nearer the horizon (the smaller cosine), beta the other's.
  const bool incidentLower = wi.z < wo.z;
  const double sinAlpha = incidentLower ? sinI : sinO;
  const double tanBeta = incidentLower ? sinO / wo.z : sinI / wi.z;
  // cos(phi_i - phi_o); 0 when either direction is the normal, where phi is undefined and sin(beta) = 0 or
  // sin(alpha) = 0 makes the term vanish anyway.
  const double cosDeltaPhi = sinI > 0.0 && sinO > 0.0 ? (wi.x * wo.x + wi.y * wo.y) / (sinI * sinO) : 0.0;
  const double term = std::max(0.0, cosDeltaPhi) * sinAlpha * tanBeta;
  return {p.rho_d * (kInvPi * (A + B * term)), dvec3(0.0)};
}

}  // namespace raylab::reference
