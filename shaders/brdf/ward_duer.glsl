// Ward with Dür's normalisation: the Ward lobe over cos_i cos_o instead of its square root.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// look: rho_d=0.4/0.1/0.5, rho_s=0.5, alpha_x=0.2, alpha_y=0.2
// figure: rho_d=0, rho_s=1, alpha_x=0.1, alpha_y=0.4 --phi 0,90
// | parameter | range      | default | kind         | meaning                       |
// |-----------|------------|---------|--------------|-------------------------------|
// | rho_d     | [0, 1]     | 0.5     | rgb diffuse  | diffuse reflectance           |
// | rho_s     | [0, 1]     | 0.5     | rgb specular | specular reflectance          |
// | alpha_x   | [0.001, 1] | 0.2     | log slope_x  | roughness along the tangent   |
// | alpha_y   | [0.001, 1] | 0.2     | log slope_y  | roughness along the bitangent |
// Dür, "An Improved Normalization for the Ward Reflectance Model", JGT 11(1), 2006; sampling of Walter 2005.
//   f = rho_d / pi + rho_s exp(-e) / (4 pi alpha_x alpha_y cos_i cos_o).
// It diverges at grazing (docs/brdfs.md).
#ifndef RAYLAB_BRDF_WARD_DUER_GLSL
#define RAYLAB_BRDF_WARD_DUER_GLSL

#include "brdf/ward_lobe.glsl"

vec3 wardDuerEval(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float e = wardExponent(halfVector(wi, wo), alphaX, alphaY);
  // exp(-e) < 1.2e-38 beyond the cut: the term is below 1e-3 even at the lifted cosines (1e-15), and
  // below 1e-19 for cosines >= 1e-7.
  if (e > kExpUnderflow) return rhoD * kInvPi;
  // cos_i cos_o >= 1e-30 after the lift: the term stays below 1e35.
  return rhoD * kInvPi + rhoS * (exp(-e) / (4.0 * kPi * alphaX * alphaY * wi.z * wo.z));
}

// The Ward lobe's sampler and density (ward_lobe.glsl) serve all three normalisations.
float wardDuerPdf(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wi, vec3 wo) {
  return wardPdf(rhoD, rhoS, alphaX, alphaY, wi, wo);
}

BsdfSample wardDuerSample(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = wardSampleDirection(rhoD, rhoS, alphaX, alphaY, wo, u);
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, wardDuerEval(rhoD, rhoS, alphaX, alphaY, wi, wo), wardPdf(rhoD, rhoS, alphaX, alphaY, wi, wo));
}

#endif
