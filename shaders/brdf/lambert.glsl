// Lambert: the ideal diffuse reflector.
// lobes: reflection diffuse
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
