// GGX conductor (Walter et al., EGSR 2007; anisotropic GGX of Heitz 2014): f = rho_s F(wi.H) D(H) G1(wi) G1(wo) /
// (4 cos_i cos_o), with the conductor's Fresnel reflectance from the complex Fresnel equations as the contract
// writes them (std::complex, principal branch), where the GLSL uses pbrt-v3's real rearrangement.
#include <complex>

#include "generated/reference_params.h"
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

}  // namespace

Lobes ggxConductorEval(const GgxConductorParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const dvec3 h = wi + wo;
  const double c = glm::dot(wi, h) / glm::length(h);
  const dvec3 F(fresnelConductor(c, p.eta.x, p.k.x), fresnelConductor(c, p.eta.y, p.k.y),
                fresnelConductor(c, p.eta.z, p.k.z));
  const double D = D_GGX(h, p.alpha_x, p.alpha_y);
  const double G = G1_GGX(wi, p.alpha_x, p.alpha_y) * G1_GGX(wo, p.alpha_x, p.alpha_y);
  return {dvec3(0.0), p.rho_s * F * (D * G / (4.0 * wi.z * wo.z))};
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
