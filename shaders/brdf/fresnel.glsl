// Fresnel reflectance of a smooth dielectric interface.
//   F_Schlick:          Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", Computer
//                       Graphics Forum 13(3), 1994.
//   F_DielectricExact:  the unpolarised Fresnel equations (Born & Wolf, "Principles of Optics", §1.5.2),
//                       F = (r_s^2 + r_p^2) / 2, rearranged below so that nothing cancels near eta = 1.
#ifndef RAYLAB_BRDF_FRESNEL_GLSL
#define RAYLAB_BRDF_FRESNEL_GLSL

#include "brdf/common.glsl"

// Reflectance at normal incidence, ((eta - 1) / (eta + 1))^2; eta - 1 is exact in float for eta in [1, 10].
float F0FromEta(float eta) {
  const float r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}

// F = F0 + (1 - F0)(1 - cos)^5. Takes 1 - cos, which each caller computes without cancellation.
float F_Schlick(float F0, float oneMinusCos) { return F0 + (1.0 - F0) * pow5(oneMinusCos); }
vec3 F_Schlick(vec3 F0, float oneMinusCos) { return F0 + (1.0 - F0) * pow5(oneMinusCos); }

// Exact unpolarised F for light arriving at cosine cosI >= 0 from the medium of index etaI into etaT.
// With d = etaT^2 - etaI^2 and A = etaT cos_t = sqrt(d + etaI^2 cosI^2) (Snell), the amplitudes are
//   r_s = (etaI cosI - A) / (etaI cosI + A) = -d / (etaI cosI + A)^2,
//   r_p = (etaT^2 cosI - etaI A) / (etaT^2 cosI + etaI A) = d ((etaT^2 + etaI^2) cosI^2 - etaI^2) / (etaT^2 cosI + etaI A)^2,
// where the textbook numerators cancel to a relative 1e-3 at eta = 1.0001 and these do not (d is a product
// of exact differences). r_p's bracket vanishes at Brewster's angle, a true zero.
float F_DielectricExact(float cosI, float etaI, float etaT) {
  const float d = (etaT - etaI) * (etaT + etaI);
  // Equal indices are no interface, even at cos_i = 0 where Snell's sin^2 theta_t reaches 1 (and the
  // amplitudes below would be 0/0).
  if (d == 0.0) return 0.0;
  const float A2 = d + etaI * etaI * cosI * cosI;
  if (A2 <= 0.0) return 1.0;  // total internal reflection: sin^2 theta_t >= 1
  const float A = sqrt(A2);
  const float s = etaI * cosI + A;                 // > 0: A > 0 here
  const float p = etaT * etaT * cosI + etaI * A;   // > 0: A > 0 here
  const float rs = -d / (s * s);
  const float rp = d * ((etaT * etaT + etaI * etaI) * cosI * cosI - etaI * etaI) / (p * p);
  // Rounding can lift F a few ulps above 1 at grazing incidence, where both amplitudes are -1.
  return min(1.0, 0.5 * (rs * rs + rp * rp));
}

#endif
