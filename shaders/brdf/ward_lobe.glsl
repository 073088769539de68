// What the three Ward variants share: the anisotropic exponent e and the sampling of its half vector.
// Ward, "Measuring and Modeling Anisotropic Reflection", SIGGRAPH 1992; sampling and its pdf from Walter,
// "Notes on the Ward BRDF", Cornell PCG technical report PCG-05-06, 2005.
#ifndef RAYLAB_BRDF_WARD_LOBE_GLSL
#define RAYLAB_BRDF_WARD_LOBE_GLSL

#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

// e = ((h_x / alpha_x)^2 + (h_y / alpha_y)^2) / h_z^2 from the components of the unnormalised h. With
// h.z >= 2e-15 (lifted directions) and alpha >= 0.001 it is at most 8e6 / 4e-30 = 2e36: finite.
float wardExponent(HalfVector hv, float alphaX, float alphaY) {
  const vec2 slope = hv.h.xy / vec2(alphaX, alphaY);
  return dot(slope, slope) / (hv.h.z * hv.h.z);
}

// Walter 2005: phi_h = atan((alpha_y / alpha_x) tan(2 pi u_z)) in the quadrant of 2 pi u_z, i.e.
// (cos phi_h, sin phi_h) along (alpha_x cos 2 pi u_z, alpha_y sin 2 pi u_z) = r (cos phi_h, sin phi_h); then
// tan^2 theta_h = -ln(1 - u_y) / (cos^2 phi_h / alpha_x^2 + sin^2 phi_h / alpha_y^2) = -ln(1 - u_y) r^2.
// So tan theta_h (cos phi_h, sin phi_h) = sqrt(-ln(1 - u_y)) (alpha_x cos 2 pi u_z, alpha_y sin 2 pi u_z).
vec3 wardSampleHalfVector(float alphaX, float alphaY, float uTheta, float uPhi) {
  const float phi = kTwoPi * uPhi;
  const float root = sqrt(-log1pAccurate(-uTheta));  // log1p(-u) stays accurate for small u
  return normalize(vec3(root * alphaX * cos(phi), root * alphaY * sin(phi), 1.0));
}

// Density of the sampled direction wi: p_h / (4 V.H) with p_h = exp(-e) / (pi alpha_x alpha_y cos^3 theta_h)
// and 1 / cos^3 = (1 + tan^2)^(3/2).
float wardSpecularPdf(HalfVector hv, float e, float alphaX, float alphaY) {
  // exp(-e) < 1.2e-38 beyond this; the cut also keeps (1 + tan^2)^(3/2) <= (1 + e)^(3/2) small.
  if (e > kExpUnderflow) return 0.0;
  const float secant2 = 1.0 + hv.tan2Theta;
  return exp(-e) * secant2 * sqrt(secant2) / (4.0 * kPi * alphaX * alphaY * hv.VoH);
}

float wardPdf(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(rhoD, rhoS);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) +
         pSpec * wardSpecularPdf(hv, wardExponent(hv, alphaX, alphaY), alphaX, alphaY);
}

// The direction of a sample of any Ward variant (its value and pdf are the caller's).
vec3 wardSampleDirection(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wo, vec3 u) {
  if (u.x < specularProbability(rhoD, rhoS)) return reflectAbout(wo, wardSampleHalfVector(alphaX, alphaY, u.y, u.z));
  return sampleCosineHemisphere(u.yz);
}

#endif
