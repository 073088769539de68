// Ashikhmin-Shirley: an anisotropic Phong lobe of the half vector with Schlick's Fresnel, and a diffuse
// term that gives way to it at grazing angles.
// lobes: reflection diffuse glossy
// sweep: Rd=0.2, Rs=0.1
// look: Rd=0.6/0.3/0.5, Rs=0.05, nu=1000, nv=40
// figure: Rd=0.5, Rs=0.5, nu=10, nv=1000 --phi 0,90
// sweep scene: nv 1 10000 log set nu=100 -> highlight_area decreasing
// sweep why: (N.H)^(nu cos^2 + nv sin^2) is half its peak on an ellipse of half-vector slopes whose area shrinks like
// sweep why: 1/sqrt(nu nv)
// (The model scales its diffuse term by (1 - Rs): in a sweep, a dielectric's small Rs keeps the body in view.
// Rs is a Fresnel reflectance, not a lobe's weight: it has no role, so switching models does not carry it.)
// | parameter | range      | default | kind           | meaning                                  |
// |-----------|------------|---------|----------------|------------------------------------------|
// | Rd        | [0, 1]     | 0.5     | rgb diffuse    | diffuse reflectance                      |
// | Rs        | [0, 1]     | 0.5     | rgb            | specular reflectance at normal incidence |
// | nu        | [1, 10000] | 100     | log exponent_x | exponent along the tangent               |
// | nv        | [1, 10000] | 100     | log exponent_y | exponent along the bitangent             |
// Ashikhmin & Shirley, "An Anisotropic Phong BRDF Model", JGT 5(2), 2000: eqs. 4 (specular), 5 (diffuse)
// and 9 (sampling).
//   spec = sqrt((nu+1)(nv+1)) / (8 pi) (N.H)^k / ((H.L) max(cos_i, cos_o)) F,  k = (nu h_x^2 + nv h_y^2) / (h_x^2 + h_y^2),
//   F = Rs + (1 - Rs)(1 - H.L)^5,
//   diff = 28 Rd / (23 pi) (1 - Rs) (1 - (1 - cos_i/2)^5)(1 - (1 - cos_o/2)^5),   f = spec + diff.
#ifndef RAYLAB_BRDF_ASHIKHMIN_SHIRLEY_GLSL
#define RAYLAB_BRDF_ASHIKHMIN_SHIRLEY_GLSL

#include "brdf/fresnel.glsl"
#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

// 1 - (1 - cos/2)^5 as x (5 - 10x + 10x^2 - 5x^3 + x^4) with x = cos/2 (Ashikhmin & Shirley 2000, eq. 5):
// the naive form cancels catastrophically at grazing (tens of percent wrong in float32 at cos = 1e-7).
float AS_diffuseFalloff(float cosTheta) {
  const float x = 0.5 * cosTheta;
  return x * (5.0 + x * (-10.0 + x * (10.0 + x * (-5.0 + x))));
}

// (N.H)^k = (1 + tan^2)^(-k/2) = exp(-(k tan^2 / 2) log1p(tan^2) / tan^2), where
// k tan^2 = (nu h_x^2 + nv h_y^2) / h_z^2 needs no division by h_x^2 + h_y^2: at h_x = h_y = 0 the lobe is
// exactly 1 (k = nu there, as the contract says) with no special case. k tan^2 <= 4e4 / 4e-30: finite.
float AS_lobe(HalfVector hv, float nu, float nv) {
  const float kTan2 = (nu * hv.h.x * hv.h.x + nv * hv.h.y * hv.h.y) / (hv.h.z * hv.h.z);
  return exp(-0.5 * kTan2 * log1pOverX(hv.tan2Theta));
}

vec3 ashikhminShirleyEval(vec3 Rd, vec3 Rs, float nu, float nv, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const HalfVector hv = halfVector(wi, wo);
  const vec3 F = F_Schlick(Rs, hv.oneMinusVoH);
  // (H.L) max(cos_i, cos_o) >= max(cos)^2 / 2 >= 5e-31 after the lift (H.L = |h|/2 >= h_z/2): finite.
  const float lobe = sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * AS_lobe(hv, nu, nv) /
                     (hv.VoH * max(wi.z, wo.z));
  const vec3 diffuse = (28.0 / (23.0 * kPi)) * Rd * (1.0 - Rs) * (AS_diffuseFalloff(wi.z) * AS_diffuseFalloff(wo.z));
  return lobe * F + diffuse;
}

// The half vector has density sqrt((nu+1)(nv+1)) / (2 pi) (N.H)^k (eq. 9); reflecting wo divides by 4 (V.H).
float ashikhminShirleyPdf(vec3 Rd, vec3 Rs, float nu, float nv, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(Rd, Rs);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) +
         pSpec * sqrt((nu + 1.0) * (nv + 1.0)) / kTwoPi * AS_lobe(hv, nu, nv) / (4.0 * hv.VoH);
}

// Eq. 9: phi_h = atan(sqrt((nu+1)/(nv+1)) tan(pi xi / 2)) over the four quadrants (pbrt and Mitsuba split u_z
// into four ranges), which is the azimuth of (sqrt(nv+1) cos 2 pi u_z, sqrt(nu+1) sin 2 pi u_z); then
// cos theta_h = (1 - u_y)^(1 / (nu cos^2 phi_h + nv sin^2 phi_h + 1)).
vec3 AS_sampleHalfVector(float nu, float nv, float uTheta, float uPhi) {
  const float phi0 = kTwoPi * uPhi;
  const vec2 azimuth = normalize(vec2(sqrt(nv + 1.0) * cos(phi0), sqrt(nu + 1.0) * sin(phi0)));
  const float k = nu * azimuth.x * azimuth.x + nv * azimuth.y * azimuth.y;
  const vec2 cs = powerCosine(1.0 - uTheta, k + 1.0);  // 1 - u is exact and in (0, 1]
  return vec3(cs.y * azimuth, cs.x);
}

BsdfSample ashikhminShirleySample(vec3 Rd, vec3 Rs, float nu, float nv, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(Rd, Rs)) {
    wi = reflectAbout(wo, AS_sampleHalfVector(nu, nv, u.y, u.z));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, ashikhminShirleyEval(Rd, Rs, nu, nv, wi, wo), ashikhminShirleyPdf(Rd, Rs, nu, nv, wi, wo));
}

#endif
