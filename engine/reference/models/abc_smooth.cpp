// Löw, Kronander, Ynnerman & Unger, "BRDF Models for Accurate and Efficient Rendering of Glossy Surfaces", ACM TOG
// 31(1), 2012, section 4: the smooth-surface model (Rayleigh-Rice with the ABC spectrum), in the form of its
// published MERL fits (docs/brdfs.md, "abc_smooth"):
//   f = rho_d / pi + A (1 + B |wi_xy + wo_xy|^2)^-C F(ior, sqrt(1 - |wi_xy - wo_xy|^2 / 4)).
// Sampling: the paper's eqs. 17-22, wi's projection on the unit disc from the density proportional to
// 1 / (1 + B |x + wo_xy|^2).
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/abc_terms.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

// L of the paper's eq. 19: the integral over the unit disc of 1 / (1 + B |x + p|^2) is pi L / B, |p| = sin(theta_o).
double logNormaliser(double b, const dvec3& wo) {
  const double q = wo.z * wo.z;
  return std::log(0.5 * (1.0 + b * q + std::sqrt(1.0 + 2.0 * b * (2.0 - q) + b * q * b * q)));
}

}  // namespace

Lobes abcSmoothEval(const AbcSmoothParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const dvec2 sum = dvec2(wi) + dvec2(wo), difference = dvec2(wi) - dvec2(wo);
  const double cosD = std::sqrt(std::max(0.0, 1.0 - 0.25 * glm::dot(difference, difference)));
  const double shape = std::pow(1.0 + p.b * glm::dot(sum, sum), -p.c);
  return {p.rho_d * kInvPi, p.a * (shape * F_DielectricFromOutside(p.ior, cosD))};
}

// u.x the radius (eqs. 20 and 22), u.y the angle from wo's azimuth (eq. 21).
dvec3 abcSmoothSampleSpecular(const AbcSmoothParams& p, const dvec3& wo, const dvec2& u) {
  const double L = logNormaliser(p.b, wo);
  const double E = 2.0 * std::exp(u.x * L);
  const double p2 = wo.x * wo.x + wo.y * wo.y;
  const double r = std::min(1.0, std::sqrt(std::expm1(u.x * L) * (E + 2.0 * p.b * p2) / (E * p.b)));
  const double radius = std::sqrt(p2);
  const double spread = std::sqrt((1.0 + p.b * (r + radius) * (r + radius)) / (1.0 + p.b * (r - radius) * (r - radius)));
  const double phiO = p2 > 0.0 ? std::atan2(wo.y, wo.x) : 0.0;
  const double phi = 2.0 * std::atan(std::tan(kPi * u.y) * spread) + phiO;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, (1.0 - r) * (1.0 + r)))};
}

double abcSmoothPdfSpecular(const AbcSmoothParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec2 sum = dvec2(wi) + dvec2(wo);
  return p.b / (kPi * logNormaliser(p.b, wo)) / (1.0 + p.b * glm::dot(sum, sum)) * wi.z;
}

// The albedo quadrature's coordinates are those of the half vector about the normal: the projected distance is
// |wi_xy + wo_xy| = 2 sin(theta_h) cos(theta_d), so the lobe falls to 1/e where the slope of h is about
// sqrt((e^(1/C) - 1) / B) / (2 cos(theta_d)), this width at cos(theta_d) = 1/2. (In the mirror direction's own
// coordinates the lobe is 1/cos(theta_o) times longer along theta than across it, which one pair of widths cannot
// follow: those coordinates missed 1% of the albedo at 60 degrees.)
SpecularLobe abcSmoothSpecularLobe(const AbcSmoothParams& p) {
  const dvec3 weight = p.a * (kPi * F0FromEta(p.ior) * abcIntegral(p.b, p.c));
  return {mixtureProbability(p.rho_d, weight), dvec2(std::min(1.0, std::sqrt(std::expm1(1.0 / p.c) / p.b))), false};
}

}  // namespace raylab::reference
