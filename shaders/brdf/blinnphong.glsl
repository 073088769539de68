// Blinn-Phong: a cosine-power lobe of the half vector around the normal plus a Lambertian term.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// look: rho_d=0.3/0.65/0.2, rho_s=0.3, s=120
// figure: rho_d=0, rho_s=1, s=50
// sweep scene: s 1 1000 log -> highlight_area decreasing
// sweep why: (N.H)^s falls to half its peak within an angle that shrinks like 1/sqrt(s), so the highlight's area at
// sweep why: half maximum shrinks like 1/s, down to a pixel
// | parameter | range      | default | kind         | meaning              |
// |-----------|------------|---------|--------------|----------------------|
// | rho_d     | [0, 1]     | 0.5     | rgb diffuse  | diffuse reflectance  |
// | rho_s     | [0, 1]     | 0.5     | rgb specular | specular reflectance |
// | s         | [1, 10000] | 50      | log exponent | specular exponent    |
// Blinn, "Models of Light Reflection for Computer Synthesized Pictures", SIGGRAPH 1977; the approximate
// normalisation (s+8)/(8 pi) of Akenine-Möller, Haines & Hoffman, "Real-Time Rendering", 3rd ed., 2008.
//   f = rho_d / pi + rho_s (s+8)/(8 pi) (N.H)^s.
// The lobe uses N.H (the slides' "angle between outgoing ray and half vector", V.H, is an erratum), and its
// albedo exceeds 1 slightly near normal incidence (about 1.075 near s = 10): docs/brdfs.md.
#ifndef RAYLAB_BRDF_BLINNPHONG_GLSL
#define RAYLAB_BRDF_BLINNPHONG_GLSL

#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

// (N.H)^s = (1 + tan^2)^(-s/2), exact at the peak and accurate near it for s = 10^4.
float blinnPhongLobe(HalfVector hv, float s) { return exp(-0.5 * s * log1pAccurate(hv.tan2Theta)); }

vec3 blinnPhongEval(vec3 rhoD, vec3 rhoS, float s, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  return rhoD * kInvPi + rhoS * ((s + 8.0) / (8.0 * kPi) * blinnPhongLobe(hv, s));
}

// The half vector has density (s+1)/(2 pi) (N.H)^s; reflecting wo about it divides by 4 (V.H) = 2 |h|.
float blinnPhongPdf(vec3 rhoD, vec3 rhoS, float s, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(rhoD, rhoS);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * (s + 1.0) / kTwoPi * blinnPhongLobe(hv, s) / (4.0 * hv.VoH);
}

BsdfSample blinnPhongSample(vec3 rhoD, vec3 rhoS, float s, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, rhoS)) {
    const vec2 cs = powerCosine(u.y, s + 1.0);
    const float phi = kTwoPi * u.z;
    wi = reflectAbout(wo, vec3(cs.y * cos(phi), cs.y * sin(phi), cs.x));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, blinnPhongEval(rhoD, rhoS, s, wi, wo), blinnPhongPdf(rhoD, rhoS, s, wi, wo));
}

#endif
