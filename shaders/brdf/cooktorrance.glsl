// Cook-Torrance: Beckmann microfacets with Schlick's Fresnel and Torrance-Sparrow shadowing, plus Lambert.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// look: rho_d=0.1/0.3/0.7, rho_s=1.0, m=0.15, eta=1.5
// figure: rho_d=0, rho_s=1, m=0.2, eta=1.5
// figure sharp_log: rho_d=0, rho_s=1, m=0.02, eta=10 --radius log
// sweep scene: m 0.01 1 log -> highlight_area increasing
// sweep why: Beckmann's D falls to half its peak within a half-vector angle that grows with m, so the highlight widens
// sweep why: (until, dimmed by the 4% Fresnel reflectance of eta 1.5, it sinks under the diffuse body, whose own
// sweep why: half-maximum area is the largest)
// sweep scene: eta 1 10 -> mean increasing
// sweep why: Schlick's F = F0 + (1 - F0)(1 - V.H)^5 grows with F0 = ((eta-1)/(eta+1))^2 at every angle
// | parameter | range       | default | kind         | meaning                                  |
// |-----------|-------------|---------|--------------|------------------------------------------|
// | rho_d     | [0, 1]      | 0.5     | rgb diffuse  | diffuse reflectance                      |
// | rho_s     | [0, 1]      | 0.5     | rgb specular | specular reflectance (F included)        |
// | m         | [0.001, 1]  | 0.2     | log slope    | Beckmann roughness (RMS slope)           |
// | eta       | [1, 10]     | 1.5     | eta          | index of refraction, inside over outside |
// Cook & Torrance, "A Reflectance Model for Computer Graphics", ACM TOG 1(1), 1982, in pbrt's form (the
// paper's own is 4x larger); sampling of Walter, Marschner, Li & Torrance, "Microfacet Models for
// Refraction through Rough Surfaces", EGSR 2007.
//   f = rho_d / pi + rho_s D F G / (4 cos_i cos_o).
#ifndef RAYLAB_BRDF_COOKTORRANCE_GLSL
#define RAYLAB_BRDF_COOKTORRANCE_GLSL

#include "brdf/fresnel.glsl"
#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

vec3 cookTorranceEval(vec3 rhoD, vec3 rhoS, float m, float eta, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const HalfVector hv = halfVector(wi, wo);
  const float D = D_Beckmann(hv.tan2Theta, m);
  const float F = F_Schlick(F0FromEta(eta), hv.oneMinusVoH);
  const float G = G_TorranceSparrow(hv.NoH, wo.z, wi.z, hv.VoH);
  // 4 cos_i cos_o >= 4e-30 after the lift, so the quotient stays below 1e35.
  return rhoD * kInvPi + rhoS * (D * F * G / (4.0 * wi.z * wo.z));
}

// The half vector has density D (N.H); reflecting wo about it divides by 4 (V.H).
float cookTorrancePdf(vec3 rhoD, vec3 rhoS, float m, float eta, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(rhoD, rhoS);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * D_Beckmann(hv.tan2Theta, m) * hv.NoH / (4.0 * hv.VoH);
}

BsdfSample cookTorranceSample(vec3 rhoD, vec3 rhoS, float m, float eta, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, rhoS)) {
    // tan^2 theta_h = -m^2 ln(1 - u), with log1p(-u) accurate for small u.
    const float tanTheta = m * sqrt(-log1pAccurate(-u.y));
    const float phi = kTwoPi * u.z;
    wi = reflectAbout(wo, normalize(vec3(tanTheta * cos(phi), tanTheta * sin(phi), 1.0)));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, cookTorranceEval(rhoD, rhoS, m, eta, wi, wo), cookTorrancePdf(rhoD, rhoS, m, eta, wi, wo));
}

#endif
