// GGX conductor: a rough metal, anisotropic GGX microfacets with the exact Fresnel term of a complex index.
// lobes: reflection glossy
// | parameter | range       | default | kind         | meaning                                        |
// |-----------|-------------|---------|--------------|------------------------------------------------|
// | alpha_x   | [0.001, 1]  | 0.2     | log slope_x  | GGX roughness along the tangent                |
// | alpha_y   | [0.001, 1]  | 0.2     | log slope_y  | GGX roughness along the bitangent              |
// | eta       | [0.01, 10]  | 0.2     | rgb          | real part of the metal's index of refraction   |
// | k         | [0, 20]     | 3       | rgb          | imaginary part (extinction coefficient)        |
// | rho_s     | [0, 1]      | 1       | rgb specular | specular scale (1: the metal as it is)         |
// Walter, Marschner, Li & Torrance, "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007, with
// the anisotropic GGX of Heitz, JCGT 3(2), 2014 (brdf/ggx.glsl), Smith's separable masking-shadowing, and the
// unpolarised Fresnel reflectance of a conductor (Born & Wolf, "Principles of Optics", §14.2), in the real
// form of pbrt-v3's FrConductor; as Mitsuba 3's roughconductor with distribution=ggx:
//   f = rho_s F(wi.H) D(H) G1(wi) G1(wo) / (4 cos_i cos_o),   H = (wi + wo) / |wi + wo|.
// Sampled by GGX visible normals (Heitz 2018). The default index is roughly silver's at 550 nm.
#ifndef RAYLAB_BRDF_GGX_CONDUCTOR_GLSL
#define RAYLAB_BRDF_GGX_CONDUCTOR_GLSL

#include "brdf/ggx.glsl"
#include "brdf/sampling.glsl"

// F of a conductor of index eta + i k (relative to the outside) at cosine c in [0, 1], per channel. t1 + t2 >= t1
// > 0 and t3 + t4 >= t3 > 0 for c > 0; at c = 0 (t2 = t4 = 0) both ratios are 1: grazing light is reflected whole.
vec3 F_Conductor(float c, vec3 eta, vec3 k) {
  const float cos2 = c * c;
  const float sin2 = 1.0 - cos2;
  const vec3 eta2 = eta * eta, k2 = k * k;
  const vec3 t0 = eta2 - k2 - sin2;
  const vec3 a2PlusB2 = sqrt(t0 * t0 + 4.0 * eta2 * k2);
  const vec3 t1 = a2PlusB2 + cos2;
  // a^2 = (|t0 + 2 i eta k| + t0) / 2; for t0 < 0 (an index below 1 near grazing) that sum cancels, and its
  // rationalised form 2 eta^2 k^2 / (|..| - t0) does not.
  const vec3 aSquared = mix(0.5 * (a2PlusB2 + t0), 2.0 * eta2 * k2 / max(a2PlusB2 - t0, vec3(1e-30)), lessThan(t0, vec3(0.0)));
  const vec3 a = sqrt(max(vec3(0.0), aSquared));
  const vec3 t2 = 2.0 * c * a;
  const vec3 rs = (t1 - t2) / (t1 + t2);
  const vec3 t3 = cos2 * a2PlusB2 + sin2 * sin2;
  const vec3 t4 = t2 * sin2;
  const vec3 rp = rs * (t3 - t4) / (t3 + t4);
  return clamp(0.5 * (rp + rs), 0.0, 1.0);
}

vec3 ggxConductorEval(float alphaX, float alphaY, vec3 eta, vec3 k, vec3 rhoS, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  precise const vec3 h = wi + wo;  // see ggxConductorPdf
  const float D = D_GGX(h, alphaX, alphaY);
  const float G = G1_GGX(wi, alphaX, alphaY) * G1_GGX(wo, alphaX, alphaY);
  // V.H = |h| / 2 for unit wi, wo (microfacet.glsl, HalfVector). 4 cos_i cos_o >= 4e-30 after the lift; D <= 3.2e5
  // and G <= 1 keep the quotient below 1e35.
  return rhoS * F_Conductor(0.5 * length(h), eta, k) * (D * G / (4.0 * wi.z * wo.z));
}

float ggxConductorPdf(float alphaX, float alphaY, vec3 eta, vec3 k, vec3 rhoS, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  // precise: inlined into the sampler, wi + wo would otherwise be folded with wi = 2 (wo.m) m - wo into an exact
  // multiple of m, and the sample's f and density would differ from bsdfEval's and bsdfPdf's of the same
  // directions by the cancellation of wi_x + wo_x at grazing (1% at wo_z = 1e-7, alpha = 0.001).
  precise const vec3 h = wi + wo;
  return ggxReflectionPdf(h, wo, alphaX, alphaY);
}

BsdfSample ggxConductorSample(float alphaX, float alphaY, vec3 eta, vec3 k, vec3 rhoS, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = reflectAbout(wo, sampleGgxVisibleNormal(liftOffHorizon(wo), alphaX, alphaY, u.yz));
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, ggxConductorEval(alphaX, alphaY, eta, k, rhoS, wi, wo),
                      ggxConductorPdf(alphaX, alphaY, eta, k, rhoS, wi, wo));
}

#endif
