// Löw's smooth-surface model: Rayleigh-Rice scattering with the ABC spectrum of the surface's heights, plus Lambert.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1
// look: rho_d=0.08/0.2/0.55, a=100, b=20000, c=1, ior=1.5
// figure: rho_d=0, a=200, b=2000, c=1, ior=1.5
// figure long_tail_log: rho_d=0, a=40, b=100000, c=0.5, ior=1.5 --radius log
// | parameter | range          | default | kind         | meaning                                                   |
// |-----------|----------------|---------|--------------|-----------------------------------------------------------|
// | rho_d     | [0, 1]         | 0.2     | rgb diffuse  | diffuse reflectance                                       |
// | a         | [0, 100000]    | 20      | rgb specular | A: the lobe's peak over its Fresnel factor (as fitted)    |
// | b         | [1, 100000000] | 2000    | log exponent | B: the inverse width in the projected distance            |
// | c         | [0.01, 4]      | 1       |              | C: the tail's exponent (small: long tails)                |
// | ior       | [1, 100]       | 1.5     | log eta      | index of refraction of the Fresnel factor                 |
// Löw, Kronander, Ynnerman & Unger, "BRDF Models for Accurate and Efficient Rendering of Glossy Surfaces", ACM TOG
// 31(1), 2012, section 4 (eqs. 10-14), in the form its published MERL fits use (Peers's bbm evaluates them so):
//   f = rho_d / pi + A (1 + B |wi_xy + wo_xy|^2)^-C Q,
// where the norm is the distance of wo's projection on the surface from wi's mirror direction's, and Q the unpolarised
// Fresnel reflectance of index ior at cos(theta_d) = sqrt(1 - |wi_xy - wo_xy|^2 / 4) (the paper's shadowing G = 1).
// Sampling (docs/brdfs.md): the paper's eqs. 17-22, wi's projection on the unit disc drawn exactly from the density
// proportional to 1 / (1 + B |x + wo_xy|^2) (the spectrum at C = 1).
#ifndef RAYLAB_BRDF_ABC_SMOOTH_GLSL
#define RAYLAB_BRDF_ABC_SMOOTH_GLSL

#include "brdf/abc.glsl"
#include "brdf/fresnel.glsl"
#include "brdf/sampling.glsl"

vec3 abcSmoothEval(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  const vec2 sum = wi.xy + wo.xy, difference = wi.xy - wo.xy;
  const float cosD = sqrt(max(0.0, 1.0 - 0.25 * dot(difference, difference)));
  return rhoD * kInvPi + a * (abcShape(b, c, dot(sum, sum)) * F_DielectricExact(cosD, 1.0, ior));
}

// log of the paper's normaliser (eq. 19): the integral over the unit disc of 1 / (1 + B |x + p|^2), |p| = sin(theta_o),
// is pi L / B with L = log((1 + B q + sqrt(1 + 2 B (2 - q) + (B q)^2)) / 2), q = cos^2(theta_o) (1 - |p|^2 without
// cancellation).
float abcSmoothLogNormaliser(float b, vec3 wo) {
  const float q = wo.z * wo.z;
  return log(0.5 * (1.0 + b * q + sqrt(1.0 + 2.0 * b * (2.0 - q) + b * q * (b * q))));
}

// The lobe's albedo at normal incidence, 2 pi A F0 times the integral of r (1 + B r^2)^-C over [0, 1]
// (= pi A F0 abcIntegral(B, C)): its share of the sampling mixture.
vec3 abcSmoothLobeWeight(vec3 a, float b, float c, float ior) {
  return a * (kPi * F0FromEta(ior) * abcIntegral(b, c));
}

// Per unit solid angle: B / (pi L) / (1 + B |wi_xy + wo_xy|^2) on the disc, times cos(theta_i).
float abcSmoothPdf(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const float pSpec = specularProbability(rhoD, abcSmoothLobeWeight(a, b, c, ior));
  const vec2 sum = wi.xy + wo.xy;
  const float disc = b / (kPi * abcSmoothLogNormaliser(b, wo)) / (1.0 + b * dot(sum, sum));
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * disc * wi.z;
}

// Eqs. 20-22: with E = 2 exp(u.y L), the radius r^2 = (E - 2)(E + 2 B |p|^2) / (2 E B) and the angle from wo's
// azimuth phi_i = 2 atan(tan(pi u.z) sqrt((1 + B (r + |p|)^2) / (1 + B (r - |p|)^2))), which crowds the samples
// about wi's mirror side (phi_o + pi).
BsdfSample abcSmoothSample(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, abcSmoothLobeWeight(a, b, c, ior))) {
    const float logNormaliser = abcSmoothLogNormaliser(b, wo);
    const float E = 2.0 * exp(u.y * logNormaliser);
    const float p2 = dot(wo.xy, wo.xy);
    const float r = min(1.0, sqrt(expm1Accurate(u.y * logNormaliser) * (E + 2.0 * b * p2) / (E * b)));
    const float p = sqrt(p2);
    const float spread = sqrt((1.0 + b * (r + p) * (r + p)) / (1.0 + b * (r - p) * (r - p)));
    const float phiO = p2 > 0.0 ? atan(wo.y, wo.x) : 0.0;  // atan(0, 0) is undefined in GLSL
    const float phi = 2.0 * atan(tan(kPi * u.z) * spread) + phiO;
    wi = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, (1.0 - r) * (1.0 + r))));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, abcSmoothEval(rhoD, a, b, c, ior, wi, wo), abcSmoothPdf(rhoD, a, b, c, ior, wi, wo));
}

#endif
