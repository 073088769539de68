// Bagher, Soler & Holzschuch, "Accurate fitting of measured reflectances using a Shifted Gamma micro-facet
// distribution", CGF 31(4), 2012, in the form of its published MERL fits (docs/brdfs.md, "sgd"), every term per
// channel:
//   f = (rho_d + rho_s F D G1(theta_i) G1(theta_o) / (cos_i cos_o)) / pi,
//   D = exp(-alpha - tan^2/alpha) / (pi (alpha + tan^2/alpha)^p cos^4), F = max(0, f0 - c f1 + (1 - c)^5 (1 - f0)),
//   G1(theta) = clamp(1 + lambda (1 - exp(c max(0, theta - theta0)^k)), 0, 1).
// Sampling: a proxy of D (half Beckmann, half a Pareto head) in y = tan^2 theta_h / a, a the geometric mean alpha.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

namespace {

// exp(-s) / s^p as one exponential (the fit evaluates this millions of times: pow is a log and an exponential).
double distribution(double alpha, double p, double tan2) {
  const double shifted = alpha + tan2 / alpha;
  return std::exp(-shifted - p * std::log(shifted)) / kPi * (1.0 + tan2) * (1.0 + tan2);
}

// From 1 - c, as (f0 - f1) + (1 - c) f1 + (1 - c)^5 (1 - f0): exact where f0 = f1 and c nears 1 (sgd.glsl).
double fresnel(double f0, double f1, double oneMinusCos) {
  const double squared = oneMinusCos * oneMinusCos;
  return std::max(0.0, (f0 - f1) + oneMinusCos * f1 + squared * squared * oneMinusCos * (1.0 - f0));
}

double shadowing(double lambda, double c, double k, double theta0, double theta) {
  const double x = theta - theta0;
  if (!(lambda > 0.0 && c > 0.0 && x > 0.0)) return 1.0;
  return std::clamp(1.0 - lambda * std::expm1(c * std::pow(x, k)), 0.0, 1.0);
}

double proxyAlpha(const SgdParams& p) { return std::cbrt(p.alpha.x * p.alpha.y * p.alpha.z); }

// A rough albedo of the lobe for the mixture, as the GLSL's: 4 rho_s (max(F(1), 0) + 0.04) alpha E with
// E = (1 - alpha^(1-p)) / (1 - p) + 1/e.
dvec3 lobeWeight(const SgdParams& p) {
  dvec3 weight;
  for (int i = 0; i < 3; ++i) {
    const double logAlpha = std::log(p.alpha[i]);
    const double E = -logAlpha * expm1OverX((1.0 - p.p[i]) * logAlpha) + std::exp(-1.0);
    weight[i] = 4.0 * p.rho_s[i] * (std::max(p.f0[i] - p.f1[i], 0.0) + 0.04) * p.alpha[i] * E;
  }
  return weight;
}

}  // namespace

Lobes sgdEval(const SgdParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const Lobes diffuseOnly{p.rho_d * kInvPi, dvec3(0.0)};
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  if (!(length > 0.0)) return diffuseOnly;
  // 1 - wi.h/|h| = 1 - |h|/2 for unit vectors, without cancellation (abc_microfacet.cpp on |h|/2).
  const double oneMinusCos = glm::dot(wi - wo, wi - wo) / (2.0 * (2.0 + length));
  const double tan2 = tan2ThetaH(h);
  // The polar angles only where a channel shadows (lambda and c > 0): most fits have none, and atan2 was an eighth
  // of a fit's time.
  double thetaI = 0.0, thetaO = 0.0;
  bool shadows = false;
  for (int i = 0; i < 3; ++i) shadows |= p.lambda[i] > 0.0 && p.c[i] > 0.0;
  if (shadows) {
    thetaI = std::atan2(std::hypot(wi.x, wi.y), wi.z);
    thetaO = std::atan2(std::hypot(wo.x, wo.y), wo.z);
  }
  dvec3 specular;
  for (int i = 0; i < 3; ++i) {
    const double G = shadowing(p.lambda[i], p.c[i], p.k[i], p.theta0[i], thetaI) *
                     shadowing(p.lambda[i], p.c[i], p.k[i], p.theta0[i], thetaO);
    specular[i] = p.rho_s[i] * fresnel(p.f0[i], p.f1[i], oneMinusCos) * distribution(p.alpha[i], p.p[i], tan2) *
                  (G / (kPi * wi.z * wo.z));
  }
  return {diffuseOnly.diffuse, specular};
}

// u.x picks the proxy's half and, rescaled to [0, 1), draws y; u.y the azimuth.
dvec3 sgdSampleSpecular(const SgdParams& p, const dvec3& wo, const dvec2& u) {
  const double a = proxyAlpha(p);
  const bool beckmann = u.x < 0.5;
  const double v = beckmann ? 2.0 * u.x : 2.0 * u.x - 1.0;
  const double y = beckmann ? -std::log1p(-v) : a * v / (1.0 - v);
  const double tan2 = a * y;
  const double cosTheta = 1.0 / std::sqrt(1.0 + tan2);
  const double sinTheta = std::sqrt(tan2) * cosTheta;
  const double phi = 2.0 * kPi * u.y;
  return reflectAbout(wo, sphericalDirection(sinTheta, cosTheta, std::cos(phi), std::sin(phi)));
}

double sgdPdfSpecular(const SgdParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  const double VoH = 0.5 * length;  // see abc_microfacet.cpp
  if (!(VoH > 0.0)) return 0.0;
  const double a = proxyAlpha(p);
  const double y = tan2ThetaH(h) / a;
  const double NoH = h.z / length;
  const double q = 0.5 * (std::exp(-y) + a / ((a + y) * (a + y)));
  return q / (kPi * a * NoH * NoH * NoH) / (4.0 * VoH);
}

// In H space the Beckmann half of the proxy is exp(-tan^2 / a): slope width sqrt(a).
SpecularLobe sgdSpecularLobe(const SgdParams& p) {
  return {mixtureProbability(p.rho_d, lobeWeight(p)), dvec2(std::sqrt(proxyAlpha(p))), false};
}

}  // namespace raylab::reference
