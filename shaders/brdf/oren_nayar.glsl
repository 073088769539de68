// Oren-Nayar: rough diffuse, Lambertian V-grooves with Gaussian slopes, in the paper's qualitative form.
// lobes: reflection diffuse
// look: rho_d=0.8/0.45/0.3, sigma=1.0
// figure: rho_d=1, sigma=0.5
// sweep scene: sigma 0 1.5 set rho_d=0.8/0.45/0.3 -> mean decreasing
// sweep why: A = 1 - sigma^2 / (2 (sigma^2 + 0.33)) scales the whole surface down as sigma grows; the B term, which
// sweep why: adds light back only where the light and the viewer are on the same side at grazing, cannot make up for it
// | parameter | range    | default | kind        | meaning                                      |
// |-----------|----------|---------|-------------|----------------------------------------------|
// | rho_d     | [0, 1]   | 0.5     | rgb diffuse | diffuse reflectance (albedo of a facet)      |
// | sigma     | [0, 1.5] | 0.5     |             | standard deviation of facet slopes (radians) |
// Oren & Nayar, "Generalization of Lambert's Reflectance Model", SIGGRAPH 1994, the qualitative model as in
// pbrt-v3's OrenNayar:
//   f = rho_d / pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
//   A = 1 - sigma^2 / (2 (sigma^2 + 0.33)),  B = 0.45 sigma^2 / (sigma^2 + 0.09),
// with alpha = max(theta_i, theta_o), beta = min: the product max(0, cos dphi) sin(alpha) tan(beta) is
// max(0, wi_x wo_x + wi_y wo_y) / max(cos_i, cos_o), written without angles (no acos, no tan at grazing).
// sigma = 0 is Lambert. Sampled cosine-weighted.
#ifndef RAYLAB_BRDF_OREN_NAYAR_GLSL
#define RAYLAB_BRDF_OREN_NAYAR_GLSL

#include "brdf/sampling.glsl"

vec3 orenNayarEval(vec3 rhoD, float sigma, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  wi = liftOffHorizon(wi);
  wo = liftOffHorizon(wo);
  const float sigma2 = sigma * sigma;
  const float A = 1.0 - sigma2 / (2.0 * (sigma2 + 0.33));
  const float B = 0.45 * sigma2 / (sigma2 + 0.09);
  // sin(alpha) tan(beta) grows as 1 / cos when both directions near the horizon (the model's own limit); the lift
  // keeps max(cos_i, cos_o) >= 1e-15, so the term stays below 1e15 and f finite.
  const float term = max(0.0, wi.x * wo.x + wi.y * wo.y) / max(wi.z, wo.z);
  return rhoD * (kInvPi * (A + B * term));
}

float orenNayarPdf(vec3 rhoD, float sigma, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  return cosineHemispherePdf(wi);
}

BsdfSample orenNayarSample(vec3 rhoD, float sigma, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = sampleCosineHemisphere(u.yz);
  return acceptSample(wi, orenNayarEval(rhoD, sigma, wi, wo), orenNayarPdf(rhoD, sigma, wi, wo));
}

#endif
