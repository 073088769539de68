// Blinn, "Models of Light Reflection for Computer Synthesized Pictures", SIGGRAPH 1977, with the usual
// approximate normalisation (s+8)/(8 pi) (Akenine-Moeller et al., Real-Time Rendering):
//   f = rho_d / pi + rho_s (s+8)/(8 pi) (N.H)^s.
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

Lobes blinnPhongEval(const BlinnPhongParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double NoHPowS = powCosThetaH(tan2ThetaH(wi + wo), p.s);
  return {p.rho_d * kInvPi, p.rho_s * ((p.s + 8.0) / (8.0 * kPi) * NoHPowS)};
}

dvec3 blinnPhongSampleSpecular(const BlinnPhongParams& p, const dvec3& wo, const dvec2& u) {
  // p_H = (s+1)/(2 pi) (N.H)^s: cos(theta_h) = u.y^(1/(s+1)), as for Phong's lobe around R.
  const PowerCosine theta = samplePowerCosine(u.x, p.s);
  const double phi = 2.0 * kPi * u.y;
  const dvec3 H = sphericalDirection(theta.sinTheta, theta.cosTheta, std::cos(phi), std::sin(phi));
  return reflectAbout(wo, H);
}

double blinnPhongPdfSpecular(const BlinnPhongParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double VoH = glm::dot(wo, h) / glm::length(h);
  // For unit wi, wo above the horizon wo.h = 1 + wi.wo > 0; only rounding of non-unit inputs gets here.
  if (!(VoH > 0.0)) return 0.0;
  const double pH = (p.s + 1.0) / (2.0 * kPi) * powCosThetaH(tan2ThetaH(h), p.s);
  return pH / (4.0 * VoH);
}

// (N.H)^s ~ exp(-s tan^2 / 2) in H space.
SpecularLobe blinnPhongSpecularLobe(const BlinnPhongParams& p) {
  return {mixtureProbability(p.rho_d, p.rho_s), dvec2(std::sqrt(2.0 / p.s)), false};
}

}  // namespace raylab::reference
