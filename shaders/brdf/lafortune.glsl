// Lafortune: generalised cosine lobes, a Lambert term plus two lobes [Cx ux vx + Cy uy vy + Cz uz vz]^n.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// fit: starts 16, a lobe's C's matter only by their ratio, a flat valley 4 starts left wrongly (docs/fitting.md)
// look: rho_d=0.15/0.35/0.5, rho_s=0.6, cx=-0.6, cy=-0.6, cz=0.55, n=80, rho_s2=0.3, cxy2=0.577, cz2=0.577, n2=4
// figure: rho_d=0, rho_s=1, cx=-0.6, cy=-0.6, cz=0.5, n=40, rho_s2=0
// figure retro: rho_d=0, rho_s=0.5, n=60, rho_s2=0.5, cxy2=0.577, cz2=0.577, n2=8
// sweep scene: rho_s2 0 1 -> mean increasing
// sweep why: the second lobe's term is linear in rho_s2 and the rest is fixed: the retro-reflective lobe (C = 0.577 in
// sweep why: each axis) sends the lamp's light back towards it, and the lamp stands near the camera
// | parameter | range      | default | kind                | meaning                                             |
// |-----------|------------|---------|---------------------|-----------------------------------------------------|
// | rho_d     | [0, 1]     | 0.5     | rgb diffuse         | diffuse reflectance                                 |
// | rho_s     | [0, 2]     | 0.5     | rgb specular        | first lobe's weight (its albedo at its peak)        |
// | cx        | [-1, 1]    | -0.577  | lobe_x              | first lobe's Cx (negative: forward scattering)      |
// | cy        | [-1, 1]    | -0.577  | lobe_y              | first lobe's Cy                                     |
// | cz        | [-1, 1]    | 0.577   |                     | first lobe's Cz                                     |
// | n         | [1, 20000] | 20      | log mirror_exponent | first lobe's exponent                               |
// | rho_s2    | [0, 2]     | 0       | rgb                 | second lobe's weight (0: one lobe, as Ngan fitted)  |
// | cxy2      | [-1, 1]    | 0.577   |                     | second lobe's Cx = Cy (positive: retro-reflection)  |
// | cz2       | [-1, 1]    | 0.577   |                     | second lobe's Cz                                    |
// | n2        | [1, 20000] | 5       | log                 | second lobe's exponent                              |
// Lafortune, Foo, Torrance & Greenberg, "Non-Linear Approximation of Reflectance Functions", SIGGRAPH 1997, eq. 4,
// each lobe normalised as Ngan, Durand & Matusik, "Experimental Analysis of BRDF Models", EGSR 2005, did:
//   f = rho_d / pi + sum_k rho_s,k (n_k + 2)/(2 pi) max(0, Cx ux vx + Cy uy vy + Cz uz vz)^n_k / max(|C|)^n_k,
// so that a lobe's peak is (n+2)/(2 pi) rho_s (with Cx = Cy = -Cz it is Phong's lobe of exponent n, exactly).
// A lobe is the cosine power about its axis a = normalize(C * wi) (the componentwise product), scaled by
// (|C * wi| / max|C|)^n: each lobe is sampled as Phong's about that axis (Lafortune & Willems 1994).
#ifndef RAYLAB_BRDF_LAFORTUNE_GLSL
#define RAYLAB_BRDF_LAFORTUNE_GLSL

#include "brdf/sampling.glsl"

// The log of a zero lobe: exp(n x) of it is 0 for every exponent, and sums of two stay finite in float.
const float kLafortuneLogZero = -1.0e30;

// log(|C * w| / max|C|) = log(1 - sum_j (1 - C_j^2 / max^2) w_j^2) / 2, accurate where the ratio is near 1 (a lobe
// with |Cx| = |Cy| = |Cz|, Ngan's fits): the direct form loses all the digits that an exponent of 10^4 amplifies.
float lafortuneLogReach(vec3 c, vec3 w) {
  const float m2 = max(max(c.x * c.x, c.y * c.y), c.z * c.z);
  if (!(m2 > 0.0)) return kLafortuneLogZero;
  const vec3 shortfall = vec3(1.0) - c * c / m2;
  return max(0.5 * log1pAccurate(-min(dot(shortfall, w * w), 1.0)), kLafortuneLogZero);
}

// log max(0, a . v) for the lobe's unit axis a, with 1 - a.v = |a - v|^2 / 2 near the peak (phong.glsl's reason).
float lafortuneLogCosine(vec3 axis, vec3 v) {
  const float c = dot(axis, v);
  if (!(c > 0.0)) return kLafortuneLogZero;
  if (c < 0.5) return max(log(c), kLafortuneLogZero);
  const vec3 d = axis - v;
  return log1pAccurate(-0.5 * dot(d, d));
}

vec3 lafortuneAxis(vec3 c, vec3 w) {
  const vec3 cw = c * w;
  const float length2 = dot(cw, cw);
  return length2 > 0.0 ? cw * inversesqrt(length2) : vec3(0.0, 0.0, 1.0);
}

// max(0, C.(wi * wo))^n / max|C|^n, symmetric in wi and wo.
float lafortuneLobe(vec3 c, float n, vec3 wi, vec3 wo) {
  const float logValue = lafortuneLogReach(c, wi) + lafortuneLogCosine(lafortuneAxis(c, wi), wo);
  return exp(n * logValue);
}

// The share of the glossy samples that go to the first lobe from wo: each lobe's weight times its reach from wo.
float lafortuneFirstLobeProbability(vec3 rhoS, vec3 c, float n, vec3 rhoS2, vec3 c2, float n2, vec3 wo) {
  const float w1 = sum3(rhoS) * exp(n * lafortuneLogReach(c, wo));
  const float w2 = sum3(rhoS2) * exp(n2 * lafortuneLogReach(c2, wo));
  return w1 + w2 > 0.0 ? w1 / (w1 + w2) : 0.5;
}

vec3 lafortuneEval(vec3 rhoD, vec3 rhoS, float cx, float cy, float cz, float n, vec3 rhoS2, float cxy2, float cz2,
                   float n2, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  return rhoD * kInvPi + rhoS * ((n + 2.0) / kTwoPi * lafortuneLobe(vec3(cx, cy, cz), n, wi, wo)) +
         rhoS2 * ((n2 + 2.0) / kTwoPi * lafortuneLobe(vec3(cxy2, cxy2, cz2), n2, wi, wo));
}

float lafortunePdf(vec3 rhoD, vec3 rhoS, float cx, float cy, float cz, float n, vec3 rhoS2, float cxy2, float cz2,
                   float n2, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const vec3 c = vec3(cx, cy, cz), c2 = vec3(cxy2, cxy2, cz2);
  const float pSpec = specularProbability(rhoD, rhoS + rhoS2);
  const float q = lafortuneFirstLobeProbability(rhoS, c, n, rhoS2, c2, n2, wo);
  const float lobe1 = (n + 1.0) / kTwoPi * exp(n * lafortuneLogCosine(lafortuneAxis(c, wo), wi));
  const float lobe2 = (n2 + 1.0) / kTwoPi * exp(n2 * lafortuneLogCosine(lafortuneAxis(c2, wo), wi));
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * (q * lobe1 + (1.0 - q) * lobe2);
}

BsdfSample lafortuneSample(vec3 rhoD, vec3 rhoS, float cx, float cy, float cz, float n, vec3 rhoS2, float cxy2,
                           float cz2, float n2, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < specularProbability(rhoD, rhoS + rhoS2)) {
    const vec3 c = vec3(cx, cy, cz), c2 = vec3(cxy2, cxy2, cz2);
    // u.y picks the lobe and, rescaled to [0, 1), draws its cosine.
    const float q = lafortuneFirstLobeProbability(rhoS, c, n, rhoS2, c2, n2, wo);
    const bool first = u.y < q;
    const float v = first ? u.y / q : (u.y - q) / (1.0 - q);
    const vec2 cs = powerCosine(min(v, 1.0), (first ? n : n2) + 1.0);
    wi = aroundAxis(lafortuneAxis(first ? c : c2, wo), cs.x, cs.y, kTwoPi * u.z);
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, lafortuneEval(rhoD, rhoS, cx, cy, cz, n, rhoS2, cxy2, cz2, n2, wi, wo),
                      lafortunePdf(rhoD, rhoS, cx, cy, cz, n, rhoS2, cxy2, cz2, n2, wi, wo));
}

#endif
