// Cook-Torrance (Cook & Torrance, "A Reflectance Model for Computer Graphics", ACM TOG 1(1), 1982) in the
// contract's form: f = rho_d/pi + rho_s D F G / (4 cos_i cos_o), Beckmann D, Schlick F, Torrance-Sparrow G.
// The 1982 paper divides by pi cos_i cos_o instead of 4 (4/pi times larger); this is the pbrt form the
// slides use (docs/brdfs.md). rho_s multiplies F as well.
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

Lobes cookTorranceEval(const CookTorranceParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const Lobes diffuseOnly{p.rho_d * kInvPi, dvec3(0.0)};
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  const double VoH = glm::dot(wo, h) / length;
  // VoH > 0 for unit wi, wo above the horizon (wo.h = 1 + wi.wo); only rounding of non-unit inputs at the
  // grazing mirror configuration (wi ~ -wo in x, y) can make it <= 0, where G would divide by it.
  if (!(VoH > 0.0)) return diffuseOnly;
  const double NoH = h.z / length;
  const double D = D_Beckmann(tan2ThetaH(h), p.m);
  const double F = F_Schlick(F0FromEta(p.eta), VoH);
  const double G = G_TorranceSparrow(NoH, wo.z, wi.z, VoH);
  return {diffuseOnly.diffuse, p.rho_s * (D * F * G / (4.0 * wi.z * wo.z))};
}

dvec3 cookTorranceSampleSpecular(const CookTorranceParams& p, const dvec3& wo, const dvec2& u) {
  // Beckmann half vector: tan^2 theta_h = -m^2 log(1 - u.y) (log1p keeps u.y near 0 accurate).
  const double tan2 = -p.m * p.m * std::log1p(-u.x);
  const double cosTheta = 1.0 / std::sqrt(1.0 + tan2);
  const double sinTheta = std::sqrt(tan2) * cosTheta;
  const double phi = 2.0 * kPi * u.y;
  return reflectAbout(wo, sphericalDirection(sinTheta, cosTheta, std::cos(phi), std::sin(phi)));
}

double cookTorrancePdfSpecular(const CookTorranceParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  const double VoH = glm::dot(wo, h) / length;
  if (!(VoH > 0.0)) return 0.0;  // see cookTorranceEval
  const double pH = D_Beckmann(tan2ThetaH(h), p.m) * (h.z / length);
  return pH / (4.0 * VoH);
}

// exp(-tan^2 / m^2) in H space.
SpecularLobe cookTorranceSpecularLobe(const CookTorranceParams& p) {
  return {mixtureProbability(p.rho_d, p.rho_s), dvec2(p.m), false};
}

}  // namespace raylab::reference
