// Ward (1992): an anisotropic Gaussian-like lobe of the half vector, plus Lambert.
// lobes: reflection diffuse glossy
// sweep: rho_d=0.1, rho_s=0.9
// look: rho_d=0.15/0.1/0.05, rho_s=0.9/0.7/0.4, alpha_x=0.08, alpha_y=0.4
// figure: rho_d=0, rho_s=1, alpha_x=0.1, alpha_y=0.4 --phi 0,90
// sweep scene: alpha_y 0.02 0.5 log set alpha_x=0.1 -> highlight_area increasing
// sweep why: the lobe exp(-(tan^2 along t / alpha_x^2 + tan^2 along b / alpha_y^2)) is half its peak on an ellipse of
// sweep why: half-vector slopes whose area grows like alpha_x alpha_y
// | parameter | range      | default | kind         | meaning                       |
// |-----------|------------|---------|--------------|-------------------------------|
// | rho_d     | [0, 1]     | 0.5     | rgb diffuse  | diffuse reflectance           |
// | rho_s     | [0, 1]     | 0.5     | rgb specular | specular reflectance          |
// | alpha_x   | [0.001, 1] | 0.2     | log slope_x  | roughness along the tangent   |
// | alpha_y   | [0.001, 1] | 0.2     | log slope_y  | roughness along the bitangent |
// Ward, "Measuring and Modeling Anisotropic Reflection", SIGGRAPH 1992 (the anisotropic form); sampling of
// Walter 2005 (ward_lobe.glsl).
//   f = rho_d / pi + rho_s exp(-e) / (4 pi alpha_x alpha_y sqrt(cos_i cos_o)).
// It loses energy and exceeds albedo 1 at grazing (docs/brdfs.md).
#ifndef RAYLAB_BRDF_WARD_GLSL
#define RAYLAB_BRDF_WARD_GLSL

#include "brdf/ward_lobe.glsl"

vec3 wardEval(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float e = wardExponent(halfVector(wi, wo), alphaX, alphaY);
  // exp(-e) < 1.2e-38 beyond the cut: the term is below 1e-17 even at the lifted cosines.
  if (e > kExpUnderflow) return rhoD * kInvPi;
  // sqrt(cos_i cos_o) >= 1e-15 after the lift.
  return rhoD * kInvPi + rhoS * (exp(-e) / (4.0 * kPi * alphaX * alphaY * sqrt(wi.z * wo.z)));
}

BsdfSample wardSample(vec3 rhoD, vec3 rhoS, float alphaX, float alphaY, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = wardSampleDirection(rhoD, rhoS, alphaX, alphaY, wo, u);
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, wardEval(rhoD, rhoS, alphaX, alphaY, wi, wo), wardPdf(rhoD, rhoS, alphaX, alphaY, wi, wo));
}

#endif
