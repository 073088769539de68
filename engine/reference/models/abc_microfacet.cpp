// Löw, Kronander, Ynnerman & Unger, "BRDF Models for Accurate and Efficient Rendering of Glossy Surfaces", ACM TOG
// 31(1), 2012: the microfacet model with the ABC distribution, in the form of the published MERL fits
// (docs/brdfs.md, "abc_microfacet"):
//   f = rho_d / pi + A F(ior, h.wi) G / ((1 + B (1 - cos theta_h))^C pi cos_i cos_o).
// Sampling: x = 1 - cos theta_h from the density proportional to (1 + B x)^-C on [0, 1] by its closed-form inverse CDF.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/abc_terms.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

// 1 - cos theta_h for the unnormalised half vector h, without the cancellation of 1 - h.z / |h|.
double oneMinusCos(const dvec3& h) {
  const double length = glm::length(h);
  return (h.x * h.x + h.y * h.y) / (length * (length + h.z));
}

double shape(const AbcMicrofacetParams& p, double x) { return std::pow(1.0 + p.b * x, -p.c); }

// The lobe's albedo at normal incidence, 8 A Z F0: its share of the sampling mixture.
dvec3 lobeWeight(const AbcMicrofacetParams& p) { return p.a * (8.0 * abcIntegral(p.b, p.c) * F0FromEta(p.ior)); }

}  // namespace

Lobes abcMicrofacetEval(const AbcMicrofacetParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const Lobes diffuseOnly{p.rho_d * kInvPi, dvec3(0.0)};
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  // wo.h / |h| = |h| / 2 for unit vectors; for float inputs, unit only to an ulp, the dot product loses every digit
  // (and its sign) where wi is nearly -wo, and |h| / 2 does not.
  const double VoH = 0.5 * length;
  if (!(VoH > 0.0)) return diffuseOnly;
  const double NoH = h.z / length;
  const double D = shape(p, oneMinusCos(h));
  const double G = G_TorranceSparrow(NoH, wo.z, wi.z, VoH);
  return {diffuseOnly.diffuse, p.a * (D * F_DielectricFromOutside(p.ior, VoH) * G / (kPi * wi.z * wo.z))};
}

// u.x draws x = 1 - cos theta_h: (1 + B x)^(1 - C) = 1 + u.x ((1 + B)^(1 - C) - 1), or (1 + B x) = (1 + B)^u.x at C = 1;
// u.y the azimuth.
dvec3 abcMicrofacetSampleSpecular(const AbcMicrofacetParams& p, const dvec3& wo, const dvec2& u) {
  const double logB = std::log1p(p.b);
  const double e = 1.0 - p.c;
  const double logOnePlusBx = e == 0.0 ? u.x * logB : std::log1p(u.x * std::expm1(e * logB)) / e;
  const double x = std::min(1.0, std::expm1(logOnePlusBx) / p.b);
  const double sinTheta = std::sqrt(std::max(0.0, x * (2.0 - x)));
  const double phi = 2.0 * kPi * u.y;
  return reflectAbout(wo, sphericalDirection(sinTheta, 1.0 - x, std::cos(phi), std::sin(phi)));
}

double abcMicrofacetPdfSpecular(const AbcMicrofacetParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  const double VoH = 0.5 * length;  // see abcMicrofacetEval
  if (!(VoH > 0.0)) return 0.0;
  const double pH = shape(p, oneMinusCos(h)) / (2.0 * kPi * abcIntegral(p.b, p.c));
  return pH / (4.0 * VoH);
}

// In H space the lobe falls to 1/e where B x = e^(1/C) - 1, at a slope of about sqrt(2 x).
SpecularLobe abcMicrofacetSpecularLobe(const AbcMicrofacetParams& p) {
  const double x = std::expm1(1.0 / p.c) / p.b;
  return {mixtureProbability(p.rho_d, lobeWeight(p)), dvec2(std::min(1.0, std::sqrt(2.0 * x))), false};
}

}  // namespace raylab::reference
