// Ashikhmin & Shirley, "An Anisotropic Phong BRDF Model", JGT 5(2), 2000 (docs/brdf_contract.md):
//   spec = sqrt((nu+1)(nv+1)) / (8 pi) (N.H)^k / ((H.L) max(cos_i, cos_o)) F,  F = Rs + (1 - Rs)(1 - H.L)^5,
//   diff = 28 Rd / (23 pi) (1 - Rs) (1 - (1 - cos_i/2)^5) (1 - (1 - cos_o/2)^5),  f = spec + diff,
// with k = (nu h_x^2 + nv h_y^2) / (h_x^2 + h_y^2) and H.L = V.H = (wo.h)/|h| (the contract's one definition).
// Sampling: the paper's eq. 9 for the half vector, reflected about wo.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

// Eq. 4: the exponent of N.H, k = (nu h_x^2 + nv h_y^2) / (h_x^2 + h_y^2) = nu cos^2 phi_h + nv sin^2 phi_h;
// nu when h_x = h_y = 0 (there N.H = 1 and the lobe factor is 1 whatever k is).
double AS_exponent(const dvec3& h, double nu, double nv) {
  // hypot and the ratios keep k a weighted mean of nu and nv even when h_x^2 + h_y^2 would underflow.
  const double r = std::hypot(h.x, h.y);
  if (r == 0.0) return nu;
  const double c = h.x / r;
  const double s = h.y / r;
  return nu * c * c + nv * s * s;
}

// Eq. 4: the lobe (N.H)^k with k = AS_exponent(h), as powCosThetaH(tan^2, k).
double AS_lobe(const dvec3& h, double nu, double nv) { return powCosThetaH(tan2ThetaH(h), AS_exponent(h, nu, nv)); }

// Eq. 5: 1 - (1 - cos/2)^5 as x (5 - 10x + 10x^2 - 5x^3 + x^4) with x = cos/2. The naive form cancels at
// grazing (cos = 1e-7 loses half the digits even in double).
double AS_diffuseFalloff(double cosTheta) {
  const double x = 0.5 * cosTheta;
  return x * (5.0 + x * (-10.0 + x * (10.0 + x * (-5.0 + x))));
}

Lobes ashikhminShirleyEval(const AshikhminShirleyParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const dvec3& Rd = p.Rd;
  const dvec3& Rs = p.Rs;
  const double nu = p.nu;
  const double nv = p.nv;
  Lobes lobes;
  lobes.diffuse =
      (28.0 / (23.0 * kPi)) * Rd * (dvec3(1.0) - Rs) * AS_diffuseFalloff(wi.z) * AS_diffuseFalloff(wo.z);
  const dvec3 h = wi + wo;
  const double HoL = glm::dot(wo, h) / glm::length(h);
  // HoL > 0 for unit wi, wo above the horizon; only rounding of non-unit inputs makes it <= 0 (see
  // cookTorranceEval), where the 1/HoL below would change sign.
  if (!(HoL > 0.0)) return lobes;
  const double lobe = AS_lobe(h, nu, nv);
  const double scale = std::sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * lobe / (HoL * std::max(wi.z, wo.z));
  lobes.specular = scale * F_Schlick(Rs, HoL);
  return lobes;
}

dvec3 ashikhminShirleySampleSpecular(const AshikhminShirleyParams& p, const dvec3& wo, const dvec2& u) {
  const double nu = p.nu;
  const double nv = p.nv;
  // First quadrant: phi = atan(sqrt((nu+1)/(nv+1)) tan(pi v / 2)) with v in [0,1); u.z picks the quadrant
  // and v is mirrored in the second and fourth so that the map stays continuous (as pbrt-v2 does).
  const double u4 = 4.0 * u.y;
  const int quadrant = std::min(3, static_cast<int>(u4));
  const double v = (quadrant % 2 == 0) ? u4 - quadrant : quadrant + 1 - u4;
  const double halfAngle = 0.5 * kPi * v;
  const double a = std::cos(halfAngle);
  const double b = std::sqrt((nu + 1.0) / (nv + 1.0)) * std::sin(halfAngle);
  const double r = std::hypot(a, b);  // > 0: cos and sin never vanish together
  double cosPhi = a / r;
  double sinPhi = b / r;
  if (quadrant == 1 || quadrant == 2) cosPhi = -cosPhi;  // phi = pi - phi1, pi + phi1
  if (quadrant == 2 || quadrant == 3) sinPhi = -sinPhi;  // phi = pi + phi1, 2 pi - phi1
  const double exponent = nu * cosPhi * cosPhi + nv * sinPhi * sinPhi;
  // cos(theta_h) = (1 - u.y)^(1/(exponent + 1)); 1 - u.y is in (0, 1].
  const PowerCosine theta = samplePowerCosine(1.0 - u.x, exponent);
  return reflectAbout(wo, sphericalDirection(theta.sinTheta, theta.cosTheta, cosPhi, sinPhi));
}

double ashikhminShirleyPdfSpecular(const AshikhminShirleyParams& p, const dvec3& wi, const dvec3& wo) {
  const double nu = p.nu;
  const double nv = p.nv;
  const dvec3 h = wi + wo;
  const double VoH = glm::dot(wo, h) / glm::length(h);
  if (!(VoH > 0.0)) return 0.0;  // see ashikhminShirleyEval
  const double pH = std::sqrt((nu + 1.0) * (nv + 1.0)) / (2.0 * kPi) * AS_lobe(h, nu, nv);
  return pH / (4.0 * VoH);
}

// (N.H)^k ~ exp(-(nu p^2 + nv q^2) / 2) in H space.
SpecularLobe ashikhminShirleySpecularLobe(const AshikhminShirleyParams& p) {
  return {mixtureProbability(p.Rd, p.Rs), {std::sqrt(2.0 / p.nu), std::sqrt(2.0 / p.nv)}, false};
}

}  // namespace raylab::reference
