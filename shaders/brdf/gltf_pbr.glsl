// glTF PBR: the metallic-roughness BRDF of the glTF 2.0 specification, Appendix B, with KHR_materials_specular.
// lobes: reflection diffuse glossy
// fit: search 4x, a plastic's faint sharp highlight (ior near 1.1, metallic near 0) is a corner 256 points miss
// sweep: metallic=1
// look: base_color=0.9/0.6/0.2, metallic=0.5, roughness=0.4
// figure: base_color=0.9/0.6/0.2, metallic=0, roughness=0.4
// sweep scene: roughness 0.1 1 set metallic=1 base_color=0.9/0.6/0.2 -> highlight_area increasing
// sweep why: GGX's D with alpha = roughness^2 is half its peak within a half-vector angle that grows with alpha, so the
// sweep why: metal's highlight widens
// | parameter      | range   | default | kind            | meaning                                         |
// |----------------|---------|---------|-----------------|-------------------------------------------------|
// | base_color     | [0, 1]  | 0.8     | rgb diffuse     | base colour: diffuse albedo, or a metal's F0    |
// | metallic       | [0, 1]  | 0       | metallic        | 0 dielectric, 1 metal, a mix between            |
// | roughness      | [0, 1]  | 0.5     | roughness       | perceptual roughness; alpha = roughness^2       |
// | ior            | [1, 3]  | 1.5     | eta             | the dielectric's index of refraction (KHR_materials_ior) |
// | specular       | [0, 1]  | 1       | specular_weight | the dielectric's specular strength, F0 and F90 (KHR_materials_specular) |
// | specular_color | [0, 25] | 1       | rgb specular_tint | colours the dielectric's F0, min(f0 colour, 1) (KHR_materials_specular) |
// The Khronos Group, "glTF 2.0 Specification", Appendix B, and the KHR_materials_specular extension (as the glTF
// Sample Renderer evaluates them):
//   alpha = max(roughness^2, 1e-3),  f0 = ((ior - 1)/(ior + 1))^2,  VH = |wo.H|,
//   D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2),
//   Vis = 0.5 / (cos_i sqrt(cos_o^2 (1 - alpha^2) + alpha^2) + cos_o sqrt(cos_i^2 (1 - alpha^2) + alpha^2)),
//   F0_d = min(f0 specular_color, 1) specular,  F_d = F0_d + (specular - F0_d)(1 - VH)^5 (RGB),
//   F_m = base_color + (1 - base_color)(1 - VH)^5,
//   f = (1 - metallic) ((1 - max(F_d)) base_color / pi + F_d Vis D) + metallic F_m Vis D.
// Vis is the height-correlated Smith G2 / (4 cos_i cos_o) (Heitz 2014). With specular = specular_color = 1 this
// is the core specification's BRDF. Sampled as a mixture: the cosine lobe or GGX visible normals (Heitz 2018), in
// proportion to (1 - metallic) base_color against the specular F0.
#ifndef RAYLAB_BRDF_GLTF_PBR_GLSL
#define RAYLAB_BRDF_GLTF_PBR_GLSL

#include "brdf/ggx.glsl"
#include "brdf/sampling.glsl"

float gltfPbrAlpha(float roughness) { return max(roughness * roughness, 1e-3); }

// The dielectric's F0 (KHR_materials_specular): the ior's, coloured and clamped to 1 before the strength scales it.
vec3 gltfPbrDielectricF0(float ior, float specular, vec3 specularColor) {
  const float f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
  return min(vec3(f0) * specularColor, vec3(1.0)) * specular;
}

// The mixture's weights: what the diffuse lobe and the specular lobe reflect at normal incidence.
float gltfPbrSpecularProbability(vec3 baseColor, float metallic, float ior, float specular, vec3 specularColor) {
  const vec3 f0 = gltfPbrDielectricF0(ior, specular, specularColor);
  return specularProbability((1.0 - metallic) * baseColor, mix(f0, baseColor, metallic));
}

vec3 gltfPbrEval(vec3 baseColor, float metallic, float roughness, float ior, float specular, vec3 specularColor,
                 vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float alpha = gltfPbrAlpha(roughness);
  const float a2 = alpha * alpha;
  precise const vec3 h = wi + wo;  // as in ggxConductorPdf: the same value inlined into the sampler or not
  // D from the components: (N.H)^2 (a^2 - 1) + 1 = (h_z^2 a^2 + h_x^2 + h_y^2) / |h|^2, which does not cancel
  // for small alpha near the peak.
  const float bracket = (h.z * h.z * a2 + dot(h.xy, h.xy)) / dot(h, h);
  const float D = a2 / (kPi * bracket * bracket);
  const float vis = 0.5 / (wi.z * sqrt(wo.z * wo.z * (1.0 - a2) + a2) + wo.z * sqrt(wi.z * wi.z * (1.0 - a2) + a2));
  const vec3 f0 = gltfPbrDielectricF0(ior, specular, specularColor);
  // 1 - V.H without cancellation: |wi - wo|^2 / (2 (2 + |h|)) (microfacet.glsl, HalfVector).
  const vec3 d = wi - wo;
  const float fresnelWeight = pow5(dot(d, d) / (2.0 * (2.0 + length(h))));
  const vec3 Fd = f0 + (vec3(specular) - f0) * fresnelWeight;
  const float FdMax = max(Fd.r, max(Fd.g, Fd.b));
  const vec3 Fm = baseColor + (vec3(1.0) - baseColor) * fresnelWeight;
  return (1.0 - metallic) * ((1.0 - FdMax) * baseColor * kInvPi + Fd * (vis * D)) + metallic * Fm * (vis * D);
}

float gltfPbrPdf(vec3 baseColor, float metallic, float roughness, float ior, float specular, vec3 specularColor,
                 vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float alpha = gltfPbrAlpha(roughness);
  const float pSpec = gltfPbrSpecularProbability(baseColor, metallic, ior, specular, specularColor);
  precise const vec3 h = wi + wo;  // as ggxConductorPdf: the same density inlined into the sampler or not
  return (1.0 - pSpec) * cosineHemispherePdf(wi) + pSpec * ggxReflectionPdf(h, wo, alpha, alpha);
}

BsdfSample gltfPbrSample(vec3 baseColor, float metallic, float roughness, float ior, float specular,
                         vec3 specularColor, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  vec3 wi;
  if (u.x < gltfPbrSpecularProbability(baseColor, metallic, ior, specular, specularColor)) {
    const float alpha = gltfPbrAlpha(roughness);
    wi = reflectAbout(wo, sampleGgxVisibleNormal(liftOffHorizon(wo), alpha, alpha, u.yz));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, gltfPbrEval(baseColor, metallic, roughness, ior, specular, specularColor, wi, wo),
                      gltfPbrPdf(baseColor, metallic, roughness, ior, specular, specularColor, wi, wo));
}

#endif
