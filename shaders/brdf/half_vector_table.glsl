// The tabulated sampler of the measured and neural BRDFs (engine/measured/measured_sampling.h): a half vector from
// a table over MERL's theta_h bins, its density piecewise linear in cos theta_h, reflected about; mixed with
// cosine-weighted directions. `table` is where the sampler's table begins in the BRDF tables (shared/brdf_tables.h).
#ifndef RAYLAB_BRDF_HALF_VECTOR_TABLE_GLSL
#define RAYLAB_BRDF_HALF_VECTOR_TABLE_GLSL

#include "brdf/brdf_tables.glsl"
#include "brdf/sampling.glsl"

// theta_h bin j spans [(j/90)^2, ((j+1)/90)^2] pi/2: the index is floor(sqrt(theta_h / (pi/2)) 90).
uint merlThetaHBin(float thetaH) {
  return uint(clamp(sqrt(max(thetaH, 0.0) / (0.5 * kPi)) * float(kMerlThetaHBins), 0.0, float(kMerlThetaHBins - 1)));
}

float merlThetaHEdgeCos(uint j) {
  const float u = float(j) / float(kMerlThetaHBins);
  return cos(u * u * 0.5 * kPi);
}

// Density of the half vector h per unit solid angle: linear in cos theta_h between the edges of its bin.
float tableHalfVectorPdf(uint table, vec3 h) {
  const uint j = merlThetaHBin(atan(length(h.xy), h.z));
  const float c0 = merlThetaHEdgeCos(j), c1 = merlThetaHEdgeCos(j + 1u);
  const float t = c0 > c1 ? clamp((c0 - h.z) / (c0 - c1), 0.0, 1.0) : 0.0;
  const float a = brdfTables[table + kSamplerDensity + j], b = brdfTables[table + kSamplerDensity + j + 1u];
  return a + t * (b - a);
}

float tablePdf(uint table, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const float pCosine = brdfTables[table + kSamplerCosineProbability];
  const vec3 h = normalize(wi + wo);
  // Reflecting wo about h divides the half vector's density by 4 (wo.h).
  return pCosine * cosineHemispherePdf(wi) + (1.0 - pCosine) * tableHalfVectorPdf(table, h) / (4.0 * dot(wo, h));
}

// A direction wi for wo (upper hemisphere) and u in [0, 1)^3; below the horizon when the reflection falls there.
vec3 tableSampleDirection(uint table, vec3 wo, vec3 u) {
  if (u.x >= 1.0 - brdfTables[table + kSamplerCosineProbability]) return sampleCosineHemisphere(u.yz);
  // The first bin whose inclusive cdf exceeds u.y (binary search over the 90 entries).
  uint lo = 0u, hi = kMerlThetaHBins - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (brdfTables[table + kSamplerCdf + mid] > u.y) hi = mid;
    else lo = mid + 1u;
  }
  const float below = lo > 0u ? brdfTables[table + kSamplerCdf + lo - 1u] : 0.0;
  const float pmf = brdfTables[table + kSamplerPmf + lo];
  const float v = pmf > 0.0 ? clamp((u.y - below) / pmf, 0.0, 1.0) : 0.5;
  // t along cos theta_h from edge lo to lo + 1, density a (1 - t) + b t: the quadratic cdf's root without
  // cancellation.
  const float a = brdfTables[table + kSamplerDensity + lo], b = brdfTables[table + kSamplerDensity + lo + 1u];
  const float t = a + b > 0.0 ? v * (a + b) / (a + sqrt(max(0.0, a * a + v * (b * b - a * a)))) : v;
  const float c0 = merlThetaHEdgeCos(lo);
  const float cosTheta = c0 + clamp(t, 0.0, 1.0) * (merlThetaHEdgeCos(lo + 1u) - c0);
  const float sinTheta = sqrt(max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
  const float phi = kTwoPi * u.z;
  return reflectAbout(wo, vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta));
}

// Rusinkiewicz's half and difference angles of (wi, wo), as the MERL database's reader computes them: wi turned
// by -phi_h about n, then by -theta_h about the bitangent. Returns the difference vector, and sin and cos theta_h.
vec3 merlDifferenceVector(vec3 wi, vec3 wo, out float sinH, out float cosH) {
  const vec3 h = normalize(wi + wo);  // wi.z + wo.z > 0: never zero
  sinH = length(h.xy);
  cosH = h.z;
  const vec2 cs = sinH > 0.0 ? h.xy / sinH : vec2(1.0, 0.0);
  const vec3 turned = vec3(wi.x * cs.x + wi.y * cs.y, wi.y * cs.x - wi.x * cs.y, wi.z);
  return vec3(turned.x * h.z - turned.z * sinH, turned.y, turned.x * sinH + turned.z * h.z);
}

#endif
