// GGX conductor (Walter et al., EGSR 2007; anisotropic GGX of Heitz 2014): f = rho_s F(wi.H) D(H) G1(wi) G1(wo) /
// (4 cos_i cos_o), with the conductor's Fresnel reflectance from the complex Fresnel equations as the contract
// writes them (std::complex, principal branch), where the GLSL uses pbrt-v3's real rearrangement; plus, with
// multiscatter, Kulla & Conty's compensation over the build-time tables the GLSL reads (generated/ggx_albedo.h).
#include <algorithm>
#include <complex>

#include "generated/reference_params.h"
#include "reference/albedo_tables.h"
#include "reference/ggx.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {
namespace {

// (|r_s|^2 + |r_p|^2) / 2 for light from outside (index 1) onto eta + i k at cosine c in [0, 1].
double fresnelConductor(double c, double eta, double k) {
  const std::complex<double> n(eta, k);
  const std::complex<double> sin2T = (1.0 - c * c) / (n * n);
  const std::complex<double> cosT = std::sqrt(1.0 - sin2T);
  const std::complex<double> rs = (c - n * cosT) / (c + n * cosT);
  const std::complex<double> rp = (n * c - cosT) / (n * c + cosT);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

// F_avg = 2 integral F(mu) mu dmu by the 8-point Gauss-Legendre rule on [0, 1]: the definition the GLSL uses too
// (docs/brdfs.md, "Multiple scattering"; about 1e-4 from the integral at worst, near the kinks of an index below 1).
double averageFresnel(double eta, double k) {
  constexpr double t[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double sum = 0.0;
  for (int n = 0; n < 4; ++n) {
    const double lo = 0.5 * (1.0 - t[n]), hi = 0.5 * (1.0 + t[n]);
    sum += w[n] * (lo * fresnelConductor(lo, eta, k) + hi * fresnelConductor(hi, eta, k));
  }
  return sum;  // 2 (mu weight) x 1/2 (the interval's Jacobian) x the weighted sum
}

// Kulla & Conty 2017: multiscatter F_ms (1 - E(cos_o)) (1 - E(cos_i)) / (pi (1 - E_avg)),
// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), at alpha = sqrt(alpha_x alpha_y).
dvec3 multipleScattering(const GgxConductorParams& p, const dvec3& wi, const dvec3& wo) {
  if (!(p.multiscatter > 0.0)) return dvec3(0.0);
  const double alpha = std::sqrt(p.alpha_x * p.alpha_y);
  const double averageLoss = ggxAverageLoss(alpha);
  if (!(averageLoss > 1e-6)) return dvec3(0.0);
  const double eAvg = 1.0 - averageLoss;
  const double lost = ggxAlbedoLoss(wo.z, alpha) * ggxAlbedoLoss(wi.z, alpha) / (kPi * averageLoss);
  dvec3 result;
  for (int c = 0; c < 3; ++c) {
    const double fAvg = averageFresnel(p.eta[c], p.k[c]);
    result[c] = p.multiscatter * fAvg * fAvg * eAvg / (1.0 - fAvg * averageLoss) * std::max(lost, 0.0);
  }
  return result;
}

}  // namespace

Lobes ggxConductorEval(const GgxConductorParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const dvec3 h = wi + wo;
  const double c = glm::dot(wi, h) / glm::length(h);
  const dvec3 F(fresnelConductor(c, p.eta.x, p.k.x), fresnelConductor(c, p.eta.y, p.k.y),
                fresnelConductor(c, p.eta.z, p.k.z));
  const double D = D_GGX(h, p.alpha_x, p.alpha_y);
  const double G = G1_GGX(wi, p.alpha_x, p.alpha_y) * G1_GGX(wo, p.alpha_x, p.alpha_y);
  return {dvec3(0.0), p.rho_s * (F * (D * G / (4.0 * wi.z * wo.z)) + multipleScattering(p, wi, wo))};
}

dvec3 ggxConductorSampleSpecular(const GgxConductorParams& p, const dvec3& wo, const dvec2& u) {
  return reflectAbout(wo, sampleGgxVisibleNormal(wo, p.alpha_x, p.alpha_y, u));
}

double ggxConductorPdfSpecular(const GgxConductorParams& p, const dvec3& wi, const dvec3& wo) {
  return ggxReflectionPdf(wi + wo, wo, p.alpha_x, p.alpha_y);
}

// Only the glossy lobe: sample() always picks it.
SpecularLobe ggxConductorSpecularLobe(const GgxConductorParams& p) {
  return {1.0, dvec2(p.alpha_x, p.alpha_y), false};
}

}  // namespace raylab::reference
