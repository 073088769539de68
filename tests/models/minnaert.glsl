// Minnaert: a darkening-limb diffuse reflector (the Moon's), a model that lives only in the test tree to show
// that registering a model is all it takes (docs/extending.md): tests/models/models.cmake registers it in test
// builds, and every per-model test then covers it.
// lobes: reflection diffuse
// | parameter | range  | default | kind        | meaning                                   |
// |-----------|--------|---------|-------------|-------------------------------------------|
// | rho_d     | [0, 1] | 0.5     | rgb diffuse | diffuse reflectance at normal incidence   |
// | k         | [1, 2] | 1.5     |             | limb darkening exponent (1: Lambert)      |
// Minnaert, "The reciprocity principle in lunar photometry", Astrophysical Journal 93, 1941, normalised so that
// the albedo at normal incidence is rho_d: f = rho_d (k+1)/(2 pi) (cos_i cos_o)^(k-1); sampled cosine-weighted.
#ifndef RAYLAB_TEST_MODELS_MINNAERT_GLSL
#define RAYLAB_TEST_MODELS_MINNAERT_GLSL

#include "brdf/sampling.glsl"

vec3 minnaertEval(vec3 rhoD, float k, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  // The lift keeps cos_i cos_o >= 1e-30, a normal float, whose power is accurate.
  const float product = liftOffHorizon(wi).z * liftOffHorizon(wo).z;
  return rhoD * ((k + 1.0) / kTwoPi * pow(product, k - 1.0));
}

float minnaertPdf(vec3 rhoD, float k, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  return cosineHemispherePdf(wi);
}

BsdfSample minnaertSample(vec3 rhoD, float k, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = sampleCosineHemisphere(u.yz);
  return acceptSample(wi, minnaertEval(rhoD, k, wi, wo), minnaertPdf(rhoD, k, wi, wo));
}

#endif
