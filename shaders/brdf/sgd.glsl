// Bagher's shifted gamma distribution (SGD): a microfacet model whose every term has its own value per colour channel.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1
// look: rho_d=0.1/0.25/0.5, rho_s=300, alpha=0.01, p=0.5, f0=0.05, f1=0, lambda=1, c=1, k=2, theta0=0.5
// figure: rho_d=0, rho_s=300, alpha=0.01, p=0.5, f0=0.05, f1=0, lambda=0
// fit: start lambda=3.06 c=5.4e-7 k=24.5 theta0=0.226, Bagher's median shadowing; lambda = c = 0 is a saddle
// figure shadowed: rho_d=0, rho_s=300, alpha=0.01, p=0.5, f0=0.05, f1=0, lambda=1, c=1, k=2, theta0=0.5
// | parameter | range          | default | kind         | meaning                                                        |
// |-----------|----------------|---------|--------------|----------------------------------------------------------------|
// | rho_d     | [0, 1]         | 0.2     | rgb diffuse  | diffuse reflectance                                            |
// | rho_s     | [0, 1000000]   | 30      | rgb specular | Bagher's rho_s times his normaliser kap                        |
// | alpha     | [0.000001, 1]  | 0.01    | rgb log      | the distribution's shift alpha (small: sharp)                  |
// | p         | [0, 2]         | 0.5     | rgb          | the gamma exponent p (large: heavy peak)                       |
// | f0        | [0, 10]        | 0.05    | rgb          | Fresnel f0: F = f0 - c f1 + (1 - c)^5 (1 - f0), c = cos(theta_d) |
// | f1        | [-1, 10]       | 0       | rgb          | Fresnel f1                                                     |
// | lambda    | [0, 100000000] | 0       | rgb          | shadowing strength lambda (0: no shadowing)                    |
// | c         | [0, 1e38]      | 0       | rgb          | shadowing scale c                                              |
// | k         | [0.1, 1000]    | 10      | rgb          | shadowing exponent k                                           |
// | theta0    | [-1, 1.5]      | 0.5     | rgb          | shadowing onset theta0 (radians)                               |
// Bagher, Soler & Holzschuch, "Accurate fitting of measured reflectances using a Shifted Gamma micro-facet
// distribution", Computer Graphics Forum 31(4), EGSR 2012, in the form of its published MERL fits (Dupuy's dj_brdf):
//   f = (rho_d + rho_s F D G1(theta_i) G1(theta_o) / (cos_i cos_o)) / pi,
//   D = exp(-alpha - tan^2/alpha) / (pi (alpha + tan^2/alpha)^p cos^4 theta_h),
//   F = f0 - c f1 + (1 - c)^5 (1 - f0) with c = wi.h, clamped at 0,
//   G1(theta) = clamp(1 + lambda (1 - exp(c max(0, theta - theta0)^k)), 0, 1).
// Sampling (docs/brdfs.md): the half vector from a proxy of D, half Beckmann and half a Pareto head, in
// y = tan^2 theta_h / alpha for the channels' geometric mean alpha.
#ifndef RAYLAB_BRDF_SGD_GLSL
#define RAYLAB_BRDF_SGD_GLSL

#include "brdf/microfacet.glsl"
#include "brdf/sampling.glsl"

// D without rho_s, per channel, in logs: exp(-alpha - t2/alpha) (alpha + t2/alpha)^-p (1 + t2)^2 / pi, where
// (1 + t2)^2 = 1/cos^4 and t2 reaches 1e30 at the lifted horizon: the exponent underflows to 0 before anything
// overflows.
vec3 sgdD(vec3 alpha, vec3 p, float tan2Theta) {
  const vec3 shifted = alpha + tan2Theta / alpha;
  const vec3 logD = -shifted - p * log(shifted) + 2.0 * log1pAccurate(tan2Theta) - log(kPi);
  return exp(max(logD, vec3(-200.0)));
}

// F = f0 - c f1 + (1 - c)^5 (1 - f0), as (f0 - f1) + (1 - c) f1 + (1 - c)^5 (1 - f0) from 1 - c: where f0 = f1, F is
// (1 - c) f1 near c = 1, which f0 - c f1 would lose to cancellation. Clamped at 0: a fit's f0 and f1 are free, and a
// reflectance may not be negative.
vec3 sgdFresnel(vec3 f0, vec3 f1, float oneMinusCos) {
  return max((f0 - f1) + oneMinusCos * f1 + pow5(oneMinusCos) * (1.0 - f0), vec3(0.0));
}

// G1(theta) = clamp(1 - lambda expm1(c max(0, theta - theta0)^k), 0, 1), with c x^k = exp(log c + k log x) (c reaches
// 1e38 and k 855 in the fits: the product stays in range where the power would not), and lambda = 0 meaning 1 (not
// 0 times an overflowed exponential).
float sgdG1Channel(float lambda, float c, float k, float theta0, float theta) {
  const float x = theta - theta0;
  if (!(lambda > 0.0 && c > 0.0 && x > 0.0)) return 1.0;
  const float y = exp(min(log(c) + k * log(x), 80.0));
  return clamp(1.0 - lambda * expm1Accurate(y), 0.0, 1.0);
}

vec3 sgdG1(vec3 lambda, vec3 c, vec3 k, vec3 theta0, vec3 w) {
  const float theta = atan(length(w.xy), w.z);  // accurate near the normal, unlike acos
  return vec3(sgdG1Channel(lambda.x, c.x, k.x, theta0.x, theta), sgdG1Channel(lambda.y, c.y, k.y, theta0.y, theta),
              sgdG1Channel(lambda.z, c.z, k.z, theta0.z, theta));
}

vec3 sgdEval(vec3 rhoD, vec3 rhoS, vec3 alpha, vec3 p, vec3 f0, vec3 f1, vec3 lambda, vec3 c, vec3 k, vec3 theta0,
             vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const HalfVector hv = halfVector(wi, wo);
  // G over the cosines first, as abc_microfacet.glsl does: the product would underflow at the horizon.
  const vec3 G = sgdG1(lambda, c, k, theta0, wi) * sgdG1(lambda, c, k, theta0, wo) / (wi.z * wo.z);
  return (rhoD + rhoS * sgdFresnel(f0, f1, hv.oneMinusVoH) * sgdD(alpha, p, hv.tan2Theta) * G) * kInvPi;
}

// The proxy's shift: the geometric mean of the channels' alpha.
float sgdProxyAlpha(vec3 alpha) { return exp((log(alpha.x) + log(alpha.y) + log(alpha.z)) / 3.0); }

// A rough albedo of the lobe for the mixture: 4 rho_s (max(F(1), 0) + 0.04) alpha E, with E the integral of
// x^-p exp(-x) over [alpha, inf) taken as that of x^-p over [alpha, 1] plus exp(-1): within a factor e of it.
vec3 sgdLobeWeight(vec3 rhoS, vec3 alpha, vec3 p, vec3 f0, vec3 f1) {
  const vec3 logAlpha = log(alpha);
  const vec3 s = (1.0 - p) * logAlpha;
  const vec3 ratio = vec3(expm1OverX(s.x), expm1OverX(s.y), expm1OverX(s.z));
  const vec3 E = -logAlpha * ratio + exp(-1.0);
  return 4.0 * rhoS * (max(f0 - f1, vec3(0.0)) + 0.04) * alpha * E;
}

// The proxy's density of y = tan^2 theta_h / a: (exp(-y) + a / (a + y)^2) / 2, so per unit solid angle of h
// q(y) / (pi a cos^3 theta_h).
float sgdProxyPdfH(float a, float tan2Theta, float NoH) {
  const float y = tan2Theta / a;
  const float q = 0.5 * (exp(-min(y, 200.0)) + a / ((a + y) * (a + y)));
  return q / (kPi * a * NoH * NoH * NoH);
}

float sgdPdf(vec3 rhoD, vec3 rhoS, vec3 alpha, vec3 p, vec3 f0, vec3 f1, vec3 lambda, vec3 c, vec3 k, vec3 theta0,
             vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const HalfVector hv = halfVector(liftOffHorizon(wi), liftOffHorizon(wo));
  const float pSpec = specularProbability(rhoD, sgdLobeWeight(rhoS, alpha, p, f0, f1));
  const float pH = sgdProxyPdfH(sgdProxyAlpha(alpha), hv.tan2Theta, hv.NoH);
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * pH / (4.0 * hv.VoH);
}

// u.y picks the proxy's half and, rescaled to [0, 1), draws y: -log(1 - v) (Beckmann) or a v / (1 - v) (Pareto).
BsdfSample sgdSample(vec3 rhoD, vec3 rhoS, vec3 alpha, vec3 p, vec3 f0, vec3 f1, vec3 lambda, vec3 c, vec3 k,
                     vec3 theta0, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, sgdLobeWeight(rhoS, alpha, p, f0, f1))) {
    const float a = sgdProxyAlpha(alpha);
    const bool beckmann = u.y < 0.5;
    const float v = beckmann ? 2.0 * u.y : 2.0 * u.y - 1.0;
    const float y = beckmann ? -log1pAccurate(-v) : a * v / (1.0 - v);
    const float tanTheta = sqrt(a * y);
    const float phi = kTwoPi * u.z;
    wi = reflectAbout(wo, normalize(vec3(tanTheta * cos(phi), tanTheta * sin(phi), 1.0)));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, sgdEval(rhoD, rhoS, alpha, p, f0, f1, lambda, c, k, theta0, wi, wo),
                      sgdPdf(rhoD, rhoS, alpha, p, f0, f1, lambda, c, k, theta0, wi, wo));
}

#endif
