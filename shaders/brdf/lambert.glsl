// Lambert: the ideal diffuse reflector.
// lobes: reflection diffuse
// look: rho_d=0.75/0.2/0.15
// figure: rho_d=1
// sweep scene: rho_d 0 1 -> mean increasing
// sweep why: the radiance rho_d/pi E cos is linear in rho_d
// sweep scene: delta 0 1 set rho_d=0.8/0.45/0.2 -> mean decreasing
// sweep why: L = (1 - delta) diffuse + delta reflected is linear in delta, and the mirror reflects the dark background
// sweep why: in its upper half and the checker floor in its lower half, darker on average than the lit orange body
// | parameter | range  | default | kind        | meaning             |
// |-----------|--------|---------|-------------|---------------------|
// | rho_d     | [0, 1] | 0.5     | rgb diffuse | diffuse reflectance |
// Lambert, "Photometria", 1760. f = rho_d / pi (docs/brdf_contract.md); sampled cosine-weighted.
#ifndef RAYLAB_BRDF_LAMBERT_GLSL
#define RAYLAB_BRDF_LAMBERT_GLSL

#include "brdf/sampling.glsl"

vec3 lambertEval(vec3 rhoD, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  return rhoD * kInvPi;
}

float lambertPdf(vec3 rhoD, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  return cosineHemispherePdf(wi);
}

BsdfSample lambertSample(vec3 rhoD, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = sampleCosineHemisphere(u.yz);
  return acceptSample(wi, lambertEval(rhoD, wi, wo), lambertPdf(rhoD, wi, wo));
}

#endif
