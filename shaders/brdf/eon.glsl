// EON: energy-preserving Oren-Nayar, the diffuse lobe of OpenPBR, in its exact-albedo form.
// lobes: reflection diffuse
// look: rho_d=0.8/0.45/0.3, r=1.0
// figure: rho_d=1, r=1
// sweep scene: r 0 1 set rho_d=0.8/0.45/0.3 -> mean steady
// sweep why: EON keeps the energy as r grows: its single scattering flattens the sphere's shading (A_F (1 + r s/t)) and
// sweep why: its multiple scattering returns the light that takes, so the mean stays put while the look changes
// | parameter | range  | default | kind        | meaning                              |
// |-----------|--------|---------|-------------|--------------------------------------|
// | rho_d     | [0, 1] | 0.5     | rgb diffuse | diffuse albedo (white: no energy lost) |
// | r         | [0, 1] | 0.5     |             | roughness                            |
// Portsmouth, Kutz & Hill, "EON: A practical energy-preserving rough diffuse BRDF", JCGT 14(1), 2025:
// Fujii's improved Oren-Nayar single scattering plus a multiple-scattering term that restores the energy it
// loses, from its exact directional albedo E_F:
//   f_ss = rho_d/pi A_F (1 + r s/t),  s = wi.wo - cos_i cos_o,  s/t = s / max(cos_i, cos_o) if s > 0 else s,
//   A_F = 1 / (1 + c1 r),  c1 = 1/2 - 2/(3 pi),
//   E_F(mu) = A_F + r A_F/pi G(mu),  G(mu) = S (acos(mu) - S mu) + 2/3 ((S/mu)(1 - S^3) - S),  S = sqrt(1 - mu^2),
//   Ebar_F = A_F (1 + c2 r),  c2 = 2/3 - 28/(15 pi),  rho_ms = rho_d^2 Ebar_F / (1 - rho_d (1 - Ebar_F)),
//   f_ms = rho_ms/pi (1 - E_F(cos_o)) (1 - E_F(cos_i)) / (1 - Ebar_F),   f = f_ss + f_ms.
// With rho_d = 1 the directional albedo is 1 for every r and angle. Sampled cosine-weighted (the paper's LTC
// sampler is optional; the cosine density stays within a factor of about 2 of f cos here).
#ifndef RAYLAB_BRDF_EON_GLSL
#define RAYLAB_BRDF_EON_GLSL

#include "brdf/sampling.glsl"

const float kEonC1 = 0.5 - 2.0 / (3.0 * kPi);
const float kEonC2 = 2.0 / 3.0 - 28.0 / (15.0 * kPi);

// The directional albedo of the single-scattering lobe with rho_d = 1. G(mu) from its terms: (S/mu)(1 - S^3)
// as S (1 - S^3) / mu = S (1 - S)(1 + S + S^2) / mu with 1 - S = mu^2 / (1 + S), which has no cancellation
// near mu = 0 and no division there either (mu^2 / mu = mu).
float eonAlbedoSingle(float mu, float r) {
  const float A = 1.0 / (1.0 + kEonC1 * r);
  const float S = sqrt(max(0.0, 1.0 - mu * mu));
  const float oneMinusS3OverMu = mu / (1.0 + S) * (1.0 + S + S * S);
  // acos(mu) as atan(S, mu): accurate at both ends on lavapipe, whose acos is off by up to 1e-4 rad.
  const float G = S * (atan(S, mu) - S * mu) + (2.0 / 3.0) * (S * oneMinusS3OverMu - S);
  return A + r * A * kInvPi * G;
}

vec3 eonEval(vec3 rhoD, float r, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  // s/t reaches 1/cos near the horizon: the lift keeps it below 1e15.
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float A = 1.0 / (1.0 + kEonC1 * r);
  const float s = dot(wi, wo) - wi.z * wo.z;
  const float sOverT = s > 0.0 ? s / max(wi.z, wo.z) : s;
  const vec3 single = rhoD * (kInvPi * A * (1.0 + r * sOverT));
  // At r = 0 the multiple-scattering term is 0/0 in the limit 0: Ebar_F = E_F = 1.
  if (!(r > 0.0)) return single;
  const float eBar = A * (1.0 + kEonC2 * r);
  const vec3 rhoMs = rhoD * rhoD * eBar / (vec3(1.0) - rhoD * (1.0 - eBar));
  const float ms = (1.0 - eonAlbedoSingle(wo.z, r)) * (1.0 - eonAlbedoSingle(wi.z, r)) / (1.0 - eBar);
  return single + rhoMs * (kInvPi * ms);
}

float eonPdf(vec3 rhoD, float r, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  return cosineHemispherePdf(wi);
}

BsdfSample eonSample(vec3 rhoD, float r, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = sampleCosineHemisphere(u.yz);
  return acceptSample(wi, eonEval(rhoD, r, wi, wo), eonPdf(rhoD, r, wi, wo));
}

#endif
