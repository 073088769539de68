// GGX dielectric: rough glass, anisotropic GGX microfacets that reflect and refract, two-sided.
// lobes: reflection transmission glossy
// look: alpha_x=0.1, alpha_y=0.1, eta=1.5
// figure: alpha_x=0.15, alpha_y=0.15, eta=1.5
// sweep scene: alpha_x 0.02 0.6 log set alpha_y=0.05 -> highlight_area increasing
// sweep why: the reflected highlight of rough glass, GGX's D on an ellipse of half-vector slopes whose area grows like
// sweep why: alpha_x alpha_y, stretches along the tangent
// | parameter | range       | default | kind        | meaning                                          |
// |-----------|-------------|---------|-------------|--------------------------------------------------|
// | alpha_x   | [0.001, 1]  | 0.1     | log slope_x | GGX roughness along the tangent                  |
// | alpha_y   | [0.001, 1]  | 0.1     | log slope_y | GGX roughness along the bitangent                |
// | eta       | [1.001, 10] | 1.5     | eta         | index of refraction, inside over outside         |
// | tint      | [0, 1]      | 1       | rgb transmittance | transmittance colour, applied as light enters |
// Walter, Marschner, Li & Torrance, "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007, with
// the anisotropic GGX terms of brdf/ggx.glsl and Smith's separable G = G1(wi) G1(wo); as Mitsuba 3's
// roughdielectric with distribution=ggx (docs/brdfs.md, "ggx_dielectric"). wi and wo may lie on either side of
// the outward normal z; eta_i, eta_o are the indices on their sides (1 outside, eta inside):
//   reflection   (cos_i cos_o > 0): f = F D(H) G / (4 |cos_i cos_o|),  H = sign(cos_o) (wi + wo)/|wi + wo|,
//   transmission (cos_i cos_o < 0): f = [tint] |wi.H| |wo.H| eta_o^2 (1 - F) D(H) G / (|cos_i cos_o| |h_t|^2),
//                h_t = -(eta_i wi + eta_o wo), H = h_t/|h_t| turned to H_z > 0 (|h_t|^2 = (eta_i wi.H + eta_o wo.H)^2),
// tint when wo is outside (a camera path entering the glass, as glass does). F is the exact dielectric Fresnel
// term; in transmission it is taken from the outside direction's cosine (the inside one loses all accuracy in
// float near the critical angle), in reflection from the side of both directions (1 beyond the critical angle).
// Sampled by visible normals seen from wo (Heitz 2018), then reflection with probability F(|wo.m|) seen from wo's
// side, else refraction through m.
#ifndef RAYLAB_BRDF_GGX_DIELECTRIC_GLSL
#define RAYLAB_BRDF_GGX_DIELECTRIC_GLSL

#include "brdf/fresnel.glsl"
#include "brdf/ggx.glsl"
#include "brdf/sampling.glsl"

// liftOffHorizon on either side: cosines of magnitude below kMinCos are raised to it, keeping their sign (the
// products of cosines in the denominators stay >= 1e-30). An exact 0 is rejected before this.
vec3 liftOffHorizonTwoSided(vec3 w) { return vec3(w.xy, w.z > 0.0 ? max(w.z, kMinCos) : min(w.z, -kMinCos)); }

// The microfacet normal of a refraction between wi and wo on opposite sides, unnormalised, with h_z >= 0:
// -(eta_i wi + eta_o wo). |h_t| >= |eta - 1| >= 0.001 for unit directions, so it never vanishes.
vec3 ggxTransmissionHalfVector(float eta, vec3 wi, vec3 wo) {
  const float etaI = wi.z > 0.0 ? 1.0 : eta;
  const float etaO = wo.z > 0.0 ? 1.0 : eta;
  precise const vec3 ht = -(etaI * wi + etaO * wo);
  return ht.z < 0.0 ? -ht : ht;
}

// Smith's separable G with the sidedness condition (w.m) w_z > 0 of each direction against m = h/|h| (h_z > 0).
float ggxSidedG(vec3 h, vec3 wi, vec3 wo, float ax, float ay) {
  if (!(dot(wi, h) * wi.z > 0.0 && dot(wo, h) * wo.z > 0.0)) return 0.0;
  return G1_GGX(wi, ax, ay) * G1_GGX(wo, ax, ay);
}

vec3 ggxDielectricEval(float alphaX, float alphaY, float eta, vec3 tint, vec3 wi, vec3 wo) {
  if (!(abs(wi.z) > 0.0 && abs(wo.z) > 0.0)) return vec3(0.0);  // on the surface, or NaN
  wi = liftOffHorizonTwoSided(wi);
  wo = liftOffHorizonTwoSided(wo);
  const float cosProduct = abs(wi.z * wo.z);
  if (wi.z * wo.z > 0.0) {
    // Reflection on wo's side: mirror both directions to the outside, where D and G are the same (they see
    // only squares of x and y), and take F with the indices of that side.
    const bool outside = wo.z > 0.0;
    const vec3 wiUp = vec3(wi.xy, abs(wi.z)), woUp = vec3(wo.xy, abs(wo.z));
    precise const vec3 h = wiUp + woUp;
    const float F = F_DielectricExact(0.5 * length(h), outside ? 1.0 : eta, outside ? eta : 1.0);
    const float D = D_GGX(h, alphaX, alphaY);
    const float G = G1_GGX(wiUp, alphaX, alphaY) * G1_GGX(woUp, alphaX, alphaY);
    return vec3(F * D * G / (4.0 * cosProduct));
  }
  const vec3 ht = ggxTransmissionHalfVector(eta, wi, wo);
  const float G = ggxSidedG(ht, wi, wo, alphaX, alphaY);
  if (!(G > 0.0)) return vec3(0.0);
  const float htLength2 = dot(ht, ht);  // >= 1e-6
  const float htLength = sqrt(htLength2);
  const vec3 wOutside = wi.z > 0.0 ? wi : wo;
  const float F = F_DielectricExact(abs(dot(wOutside, ht)) / htLength, 1.0, eta);
  const float etaO = wo.z > 0.0 ? 1.0 : eta;
  // |wi.H| |wo.H| / (eta_i wi.H + eta_o wo.H)^2 = |wi.h_t| |wo.h_t| / |h_t|^4; each cosine ratio <= 1 / 1e-15.
  const float geometry = (abs(dot(wi, ht)) / htLength2) * (abs(dot(wo, ht)) / htLength2) / cosProduct;
  const float value = etaO * etaO * (1.0 - F) * D_GGX(ht, alphaX, alphaY) * G * geometry;
  return wo.z > 0.0 ? tint * value : vec3(value);
}

// The probability of choosing reflection for the viewer wo at cosine cosO = |wo.m| to the microfacet: the Fresnel
// term seen from wo's side, 1 beyond the critical angle.
float ggxReflectProbability(float eta, float cosO, bool outside) {
  return F_DielectricExact(cosO, outside ? 1.0 : eta, outside ? eta : 1.0);
}

float ggxDielectricPdf(float alphaX, float alphaY, float eta, vec3 tint, vec3 wi, vec3 wo) {
  if (!(abs(wi.z) > 0.0 && abs(wo.z) > 0.0)) return 0.0;
  wi = liftOffHorizonTwoSided(wi);
  wo = liftOffHorizonTwoSided(wo);
  const vec3 woUp = vec3(wo.xy, abs(wo.z));
  if (wi.z * wo.z > 0.0) {
    precise const vec3 h = vec3(wi.xy, abs(wi.z)) + woUp;  // see ggxConductorPdf
    return ggxReflectProbability(eta, dot(woUp, h) / length(h), wo.z > 0.0) * ggxReflectionPdf(h, woUp, alphaX, alphaY);
  }
  const vec3 ht = ggxTransmissionHalfVector(eta, wi, wo);
  if (!(dot(wi, ht) * wi.z > 0.0 && dot(wo, ht) * wo.z > 0.0)) return 0.0;
  // D_wo(m) = G1(wo) |wo.m| D(m) / |cos_o|, times dm/dwi = eta_i^2 |wi.m| / |h_t|^2, for m = h_t / |h_t|:
  // G1 D eta_i^2 |wo.h_t| |wi.h_t| / (|cos_o| |h_t|^4).
  const float etaI = wi.z > 0.0 ? 1.0 : eta;
  const float htLength2 = dot(ht, ht);
  const float visible = G1_GGX(woUp, alphaX, alphaY) * (abs(dot(wo, ht)) / htLength2) * D_GGX(ht, alphaX, alphaY) / woUp.z;
  const float reflectProbability = ggxReflectProbability(eta, abs(dot(wo, ht)) / sqrt(htLength2), wo.z > 0.0);
  return (1.0 - reflectProbability) * visible * etaI * etaI * (abs(dot(wi, ht)) / htLength2);
}

BsdfSample ggxDielectricSample(float alphaX, float alphaY, float eta, vec3 tint, vec3 wo, vec3 u) {
  if (!(abs(wo.z) > 0.0)) return noSample();
  const vec3 woLifted = liftOffHorizonTwoSided(wo);
  const bool outside = wo.z > 0.0;
  // m faces wo: drawn for wo mirrored to the outside, then mirrored back to wo's side (D is symmetric).
  const vec3 mUp = sampleGgxVisibleNormal(vec3(woLifted.xy, abs(woLifted.z)), alphaX, alphaY, u.yz);
  const vec3 m = outside ? mUp : vec3(mUp.xy, -mUp.z);
  const float cosO = dot(wo, m);  // > 0 for a visible normal
  vec3 wi;
  if (u.x < ggxReflectProbability(eta, cosO, outside)) {
    wi = 2.0 * cosO * m - wo;
    if (!(wi.z * wo.z > 0.0)) return noSample();
  } else {
    // Snell through m, written as glassEvent's refraction (brdf/glass.glsl): A2 = (eta_t cos_t)^2.
    const float etaO = outside ? 1.0 : eta, etaT = outside ? eta : 1.0;
    const float A2 = (etaT - etaO) * (etaT + etaO) + etaO * etaO * cosO * cosO;
    if (!(A2 > 0.0)) return noSample();  // total internal reflection: its probability was 1
    const float ratio = etaO / etaT;
    wi = -ratio * (wo - cosO * m) - (sqrt(A2) / etaT) * m;
    if (!(wi.z * wo.z < 0.0)) return noSample();
  }
  const float pdf = ggxDielectricPdf(alphaX, alphaY, eta, tint, wi, wo);
  if (!(pdf > 0.0)) return noSample();
  return BsdfSample(wi, ggxDielectricEval(alphaX, alphaY, eta, tint, wi, wo), pdf);
}

#endif
