// Phong, "Illumination for Computer Generated Pictures", CACM 18(6), 1975, in the energy-normalised form of
// Lewis, "Making Shaders More Physically Plausible", CGF 13(2), 1994 (docs/brdf_contract.md, "Formulas"):
//   f = rho_d / pi + rho_s (s+2)/(2 pi) max(0, R.wo)^s.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

// R = 2 (n.w) n - w is (-w.x, -w.y, w.z) in the local frame, so R_i.wo = R_o.wi: one symmetric expression.
double mirrorCosine(const dvec3& wi, const dvec3& wo) { return wi.z * wo.z - wi.x * wo.x - wi.y * wo.y; }

}  // namespace

Lobes phongEval(const PhongParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double c = std::max(0.0, mirrorCosine(wi, wo));
  return {p.rho_d * kInvPi, p.rho_s * ((p.s + 2.0) / (2.0 * kPi) * std::pow(c, p.s))};
}

dvec3 phongSampleSpecular(const PhongParams& p, const dvec3& wo, const dvec2& u) {
  const dvec3 R(-wo.x, -wo.y, wo.z);
  // Any fixed frame around R serves; this one is the frame of shaders/common/frame.glsl for a zero tangent
  // hint (Duff et al. 2017), so that the GPU can produce the very same directions.
  const Frame frame = makeFrame(R, dvec3(0.0));
  const PowerCosine alpha = samplePowerCosine(u.x, p.s);
  const double phi = 2.0 * kPi * u.y;
  return alpha.sinTheta * std::cos(phi) * frame.t + alpha.sinTheta * std::sin(phi) * frame.b +
         alpha.cosTheta * frame.n;
}

double phongPdfSpecular(const PhongParams& p, const dvec3& wi, const dvec3& wo) {
  return (p.s + 1.0) / (2.0 * kPi) * std::pow(std::max(0.0, mirrorCosine(wi, wo)), p.s);
}

// c^s ~ exp(-s beta^2 / 2) around R, in wi space.
SpecularLobe phongSpecularLobe(const PhongParams& p) {
  return {mixtureProbability(p.rho_d, p.rho_s), dvec2(std::sqrt(2.0 / p.s)), true};
}

}  // namespace raylab::reference
