// The fuzz layer's lobe (OpenPBR 1.1.1, "Fuzz"; Zeltner, Burley & Chiang, "Practical Multiple-Scattering Sheen Using
// Linearly Transformed Cosines", 2022), as engine/reference/fuzz.h defines it:
//   f_fuzz(wi, wo) cos_i = E_fuzz(mu_o, r) D(wi | wo),  D(w) = w.z a^2 / (pi |M^-1 w|^4),
// M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]] in wo's azimuthal frame; (E_fuzz, a, b) bilinear in the BRDF tables,
// fitted to a fibre volume's random walk (engine/reference/fuzz_volume.h). D integrates to 1 and is sampled exactly.
#ifndef RAYLAB_BRDF_FUZZ_GLSL
#define RAYLAB_BRDF_FUZZ_GLSL

#include "brdf/brdf_tables.glsl"
#include "brdf/sampling.glsl"

// (E_fuzz, a, b) at (mu, roughness).
vec3 fuzzLobe(float mu, float roughness) {
  const float last = float(kFuzzLtcSize - 1u);
  const float x = clamp(mu, 0.0, 1.0) * last, y = clamp(roughness, 0.0, 1.0) * last;
  const uint j = min(uint(x), kFuzzLtcSize - 2u), i = min(uint(y), kFuzzLtcSize - 2u);
  const uint k = kFuzzLtcOffset + 3u * (i * kFuzzLtcSize + j), up = 3u * kFuzzLtcSize;
  const vec3 v00 = vec3(brdfTables[k], brdfTables[k + 1u], brdfTables[k + 2u]);
  const vec3 v01 = vec3(brdfTables[k + 3u], brdfTables[k + 4u], brdfTables[k + 5u]);
  const vec3 v10 = vec3(brdfTables[k + up], brdfTables[k + up + 1u], brdfTables[k + up + 2u]);
  const vec3 v11 = vec3(brdfTables[k + up + 3u], brdfTables[k + up + 4u], brdfTables[k + up + 5u]);
  const float tx = x - float(j);
  return mix(mix(v00, v01, tx), mix(v10, v11, tx), y - float(i));
}

// cos and sin of wo's azimuth; (1, 0) at the normal, where D is round.
vec2 fuzzAzimuth(vec3 wo) {
  const float length2 = wo.x * wo.x + wo.y * wo.y;
  return length2 > 0.0 ? wo.xy * inversesqrt(length2) : vec2(1.0, 0.0);
}

// D(wi | wo) per unit solid angle; lobe = fuzzLobe(wo.z, r).
float fuzzDensity(vec3 wi, vec3 wo, vec3 lobe) {
  if (!(wi.z > 0.0)) return 0.0;
  const vec2 phi = fuzzAzimuth(wo);
  const float x = phi.x * wi.x + phi.y * wi.y, y = phi.x * wi.y - phi.y * wi.x;
  const vec3 q = vec3(lobe.y * x + lobe.z * wi.z, lobe.y * y, wi.z);
  const float q2 = dot(q, q);
  return wi.z * lobe.y * lobe.y / (kPi * q2 * q2);
}

// A direction from D(. | wo): a cosine-distributed one through M, back from wo's azimuthal frame.
vec3 sampleFuzz(vec3 wo, vec3 lobe, vec2 u) {
  const vec3 c = sampleCosineHemisphere(u);
  const vec3 local = vec3((c.x - lobe.z * c.z) / lobe.y, c.y / lobe.y, c.z);
  const vec2 phi = fuzzAzimuth(wo);
  return normalize(vec3(phi.x * local.x - phi.y * local.y, phi.y * local.x + phi.x * local.y, local.z));
}

#endif
