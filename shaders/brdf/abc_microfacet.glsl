// Löw's microfacet model: the ABC distribution of half vectors, V-groove shadowing and the exact Fresnel, plus Lambert.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1
// look: rho_d=0.08/0.2/0.55, a=400, b=20000, c=1, ior=1.5
// figure: rho_d=0, a=100, b=2000, c=1, ior=1.5
// figure heavy_tail_log: rho_d=0, a=300, b=260000, c=0.7, ior=1.5 --radius log
// | parameter | range         | default | kind         | meaning                                                    |
// |-----------|---------------|---------|--------------|------------------------------------------------------------|
// | rho_d     | [0, 1]        | 0.2     | rgb diffuse  | diffuse reflectance                                        |
// | a         | [0, 100000]   | 100     | rgb specular | A: the distribution's peak (unnormalised, as Löw fitted it) |
// | b         | [1, 100000000] | 10000  | log exponent | B: the inverse width in 1 - cos(theta_h)                   |
// | c         | [0.01, 4]     | 1       |              | C: the tail's exponent (small: long tails)                 |
// | ior       | [1, 100]      | 1.5     | log eta      | index of refraction of the exact Fresnel term              |
// Löw, Kronander, Ynnerman & Unger, "BRDF Models for Accurate and Efficient Rendering of Glossy Surfaces", ACM TOG
// 31(1), 2012, section 5, in the form its published MERL fits use (their supplemental tables, Dupuy's dj_brdf and
// Peers's bbm agree; the paper's eq. 15 has no 1/pi, the fits do):
//   f = rho_d / pi + A F(ior, h.wi) G / ((1 + B (1 - cos theta_h))^C pi cos_i cos_o),
// G the V-groove term of Torrance & Sparrow, F the unpolarised Fresnel reflectance of a dielectric of index ior.
// Sampling (docs/brdfs.md): the half vector exactly from the density proportional to (1 + B x)^-C in x = 1 - cos theta_h
// (uniform azimuth), whose inverse CDF is closed-form; the lobe's share of the mixture is its normal-incidence albedo
// 8 A Z F0 with Z = the integral of (1 + B x)^-C over [0, 1].
#ifndef RAYLAB_BRDF_ABC_MICROFACET_GLSL
#define RAYLAB_BRDF_ABC_MICROFACET_GLSL

#include "brdf/abc.glsl"
#include "brdf/fresnel.glsl"
#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

// x = 1 - cos theta_h of the unnormalised half vector h, as (h_x^2 + h_y^2) / (|h| (|h| + h_z)): B up to 1e8 scales
// x, and 1 - h_z / |h| loses every digit of it in float for the narrow lobes.
float abcOneMinusCos(HalfVector hv) {
  return dot(hv.h.xy, hv.h.xy) / (hv.len * (hv.len + hv.h.z));
}

vec3 abcMicrofacetEval(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const HalfVector hv = halfVector(wi, wo);
  const float D = abcShape(b, c, abcOneMinusCos(hv));
  const float F = F_DielectricExact(hv.VoH, 1.0, ior);
  const float G = G_TorranceSparrow(hv.NoH, wo.z, wi.z, hv.VoH);
  // G over the cosines first: at the horizon each is 1e-15, and D F G would underflow before the division.
  return rhoD * kInvPi + a * (D * F * (G / (kPi * wi.z * wo.z)));
}

// The lobe's albedo at normal incidence, 8 A Z F0: its share of the sampling mixture.
vec3 abcLobeWeight(vec3 a, float b, float c, float ior) {
  return a * (8.0 * F0FromEta(ior) * abcIntegral(b, c));
}

// The half vector's density (1 + B x)^-C / (2 pi Z) per unit solid angle; reflecting wo divides by 4 (V.H).
float abcMicrofacetPdf(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(rhoD, abcLobeWeight(a, b, c, ior));
  const float pH = abcShape(b, c, abcOneMinusCos(hv)) / (kTwoPi * abcIntegral(b, c));
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * pH / (4.0 * hv.VoH);
}

// x with the integral of (1 + B x')^-C over [0, x] equal to u Z: log(1 + B x) = log1p(u expm1(s)) / (1 - C), which
// tends to u log(1 + B) (1 + (1 - u) s / 2) as s = (1 - C) log(1 + B) tends to 0.
float abcSampleOneMinusCos(float b, float c, float u) {
  const float logB = log1pAccurate(b);
  const float s = (1.0 - c) * logB;
  const float logOnePlusBx = abs(s) < 1.0e-3 ? u * logB * (1.0 + 0.5 * (1.0 - u) * s)
                                             : log1pAccurate(u * expm1Accurate(s)) / (1.0 - c);
  return min(1.0, expm1Accurate(logOnePlusBx) / b);
}

BsdfSample abcMicrofacetSample(vec3 rhoD, vec3 a, float b, float c, float ior, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, abcLobeWeight(a, b, c, ior))) {
    const float x = abcSampleOneMinusCos(b, c, u.y);
    const float sinTheta = sqrt(max(x * (2.0 - x), 0.0));  // exact for the tiny x of narrow lobes
    const float phi = kTwoPi * u.z;
    wi = reflectAbout(wo, vec3(sinTheta * cos(phi), sinTheta * sin(phi), 1.0 - x));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, abcMicrofacetEval(rhoD, a, b, c, ior, wi, wo), abcMicrofacetPdf(rhoD, a, b, c, ior, wi, wo));
}

#endif
