// Lambert, Phong and Blinn-Phong (docs/brdf_contract.md, "Formulas").
//   Lambert (1760): f = rho_d / pi.
//   Phong, "Illumination for Computer Generated Pictures", CACM 18(6), 1975, in the energy-normalised form of
//   Lewis, "Making Shaders More Physically Plausible", CGF 13(2), 1994: + rho_s (s+2)/(2 pi) max(0, R.wo)^s.
//   Blinn, "Models of Light Reflection for Computer Synthesized Pictures", SIGGRAPH 1977, with the usual
//   approximate normalisation (s+8)/(8 pi) (Akenine-Moeller et al., Real-Time Rendering): + rho_s (N.H)^s.
#include <algorithm>
#include <cmath>

#include "reference/models.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

// R = 2 (n.w) n - w is (-w.x, -w.y, w.z) in the local frame, so R_i.wo = R_o.wi: one symmetric expression.
double mirrorCosine(const dvec3& wi, const dvec3& wo) { return wi.z * wo.z - wi.x * wo.x - wi.y * wo.y; }

}  // namespace

Lobes lambertEval(const Material& material, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {material.rhoD * kInvPi, dvec3(0.0)};
}

Lobes phongEval(const Material& material, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double s = material.s;
  const double c = std::max(0.0, mirrorCosine(wi, wo));
  return {material.rhoD * kInvPi, material.rhoS * ((s + 2.0) / (2.0 * kPi) * std::pow(c, s))};
}

dvec3 phongSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u) {
  const dvec3 R(-wo.x, -wo.y, wo.z);
  // Any fixed frame around R serves; this one is the frame of shaders/common/frame.glsl for a zero tangent
  // hint (Duff et al. 2017), so that the GPU can produce the very same directions.
  const Frame frame = makeFrame(R, dvec3(0.0));
  const PowerCosine alpha = samplePowerCosine(u.x, material.s);
  const double phi = 2.0 * kPi * u.y;
  return alpha.sinTheta * std::cos(phi) * frame.t + alpha.sinTheta * std::sin(phi) * frame.b +
         alpha.cosTheta * frame.n;
}

double phongPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo) {
  const double s = material.s;
  return (s + 1.0) / (2.0 * kPi) * std::pow(std::max(0.0, mirrorCosine(wi, wo)), s);
}

Lobes blinnPhongEval(const Material& material, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double s = material.s;
  const double NoHPowS = powCosThetaH(tan2ThetaH(wi + wo), s);
  return {material.rhoD * kInvPi, material.rhoS * ((s + 8.0) / (8.0 * kPi) * NoHPowS)};
}

dvec3 blinnPhongSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u) {
  // p_H = (s+1)/(2 pi) (N.H)^s: cos(theta_h) = u.y^(1/(s+1)), as for Phong's lobe around R.
  const PowerCosine theta = samplePowerCosine(u.x, material.s);
  const double phi = 2.0 * kPi * u.y;
  const dvec3 H = sphericalDirection(theta.sinTheta, theta.cosTheta, std::cos(phi), std::sin(phi));
  return reflectAbout(wo, H);
}

double blinnPhongPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double VoH = glm::dot(wo, h) / glm::length(h);
  // For unit wi, wo above the horizon wo.h = 1 + wi.wo > 0; only rounding of non-unit inputs gets here.
  if (!(VoH > 0.0)) return 0.0;
  const double s = material.s;
  const double pH = (s + 1.0) / (2.0 * kPi) * powCosThetaH(tan2ThetaH(h), s);
  return pH / (4.0 * VoH);
}

}  // namespace raylab::reference
