// Phong, energy-normalised: a cosine-power lobe around the mirror direction plus a Lambertian term.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// look: rho_d=0.7/0.5/0.1, rho_s=0.3, s=60
// figure: rho_d=0, rho_s=1, s=50
// sweep scene: rho_s 0 1 -> mean increasing
// sweep why: the specular term is linear in rho_s and the diffuse term is fixed
// sweep scene: s 1 1000 log -> highlight_area decreasing
// sweep why: cos^s falls to half its peak within an angle that shrinks like 1/sqrt(s), so the highlight's area at half
// sweep why: maximum shrinks like 1/s, down to a pixel
// | parameter | range      | default | kind                | meaning              |
// |-----------|------------|---------|---------------------|----------------------|
// | rho_d     | [0, 1]     | 0.5     | rgb diffuse         | diffuse reflectance  |
// | rho_s     | [0, 1]     | 0.5     | rgb specular        | specular reflectance |
// | s         | [1, 10000] | 50      | log mirror_exponent | specular exponent    |
// Phong, "Illumination for Computer Generated Pictures", CACM 18(6), 1975; normalisation (s+2)/(2 pi) from
// Lewis, "Making Shaders More Physically Plausible", CGF 13(2), 1994, and Lafortune & Willems, "Using the
// Modified Phong Reflectance Model for Physically Based Rendering", 1994 (also the sampling).
//   f = rho_d / pi + rho_s (s+2)/(2 pi) max(0, R.wo)^s,   R = 2 (n.wi) n - wi.
#ifndef RAYLAB_BRDF_PHONG_GLSL
#define RAYLAB_BRDF_PHONG_GLSL

#include "brdf/sampling.glsl"

// max(0, R.wo)^s with R the mirror of wi about n (symmetric in wi and wo), in the form accurate in each
// regime. Near the peak (R.wo >= 1/2), 1 - R.wo = |R - wo|^2 / 2 carries no cancellation, where 1 - dot(R, wo)
// would lose all the accuracy that matters for s = 10^4; the power is exp(s log1p(-x)) for the reason in
// common.glsl. Far from it the cosine itself is accurate and 1 - |R - wo|^2 / 2 is not: at R.wo = 1e-7 that
// form is off by 20% or rounds to 0 (grazing wi or wo).
float phongLobe(vec3 wi, vec3 wo, float s) {
  const vec3 r = vec3(-wi.xy, wi.z);
  const float c = dot(r, wo);
  if (!(c > 0.0)) return 0.0;
  if (c < 0.5) return exp(s * log(c));
  const vec3 d = r - wo;
  return exp(s * log1pAccurate(-0.5 * dot(d, d)));
}

vec3 phongEval(vec3 rhoD, vec3 rhoS, float s, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  return rhoD * kInvPi + rhoS * ((s + 2.0) / kTwoPi * phongLobe(wi, wo, s));
}

float phongPdf(vec3 rhoD, vec3 rhoS, float s, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const float pSpec = specularProbability(rhoD, rhoS);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * (s + 1.0) / kTwoPi * phongLobe(wi, wo, s);
}

BsdfSample phongSample(vec3 rhoD, vec3 rhoS, float s, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, rhoS)) {
    const vec2 cs = powerCosine(u.y, s + 1.0);
    wi = aroundAxis(vec3(-wo.xy, wo.z), cs.x, cs.y, kTwoPi * u.z);
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, phongEval(rhoD, rhoS, s, wi, wo), phongPdf(rhoD, rhoS, s, wi, wo));
}

#endif
