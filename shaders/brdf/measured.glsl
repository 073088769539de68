// Measured: a MERL BRDF database file (Matusik, Pfister, Brand & McMillan, "A Data-Driven Reflectance Model",
// SIGGRAPH 2003), looked up as the database's own reader does: Rusinkiewicz's half/difference angles, the
// non-linear theta_h axis, the nearest sample, missing samples 0 (docs/brdfs.md, "measured").
// lobes: reflection glossy
// | parameter | range          | default | kind | meaning                                              |
// |-----------|----------------|---------|------|------------------------------------------------------|
// | file      | [0, 16777215]  | 0       | file | the MERL .binary file, a path (relative to the scene) |
// Rusinkiewicz, "A New Change of Variables for Efficient BRDF Representation", EGWR 1998. Sampling: a half
// vector from the file's table over the theta_h bins (piecewise linear in cos theta_h), mixed with cosine-weighted
// directions (engine/measured/measured_sampling.h); the block of the BRDF tables buffer holding the file is `file`.
#ifndef RAYLAB_BRDF_MEASURED_GLSL
#define RAYLAB_BRDF_MEASURED_GLSL

#include "brdf/brdf_tables.glsl"
#include "brdf/sampling.glsl"

uint measuredBlock(float file) { return kMeasuredOffset + uint(file) * kMeasuredBlockFloats; }

// theta_h bin j spans [(j/90)^2, ((j+1)/90)^2] pi/2: the index is floor(sqrt(theta_h / (pi/2)) 90).
uint measuredThetaHBin(float thetaH) {
  return uint(clamp(sqrt(max(thetaH, 0.0) / (0.5 * kPi)) * float(kMerlThetaHBins), 0.0, float(kMerlThetaHBins - 1)));
}

float measuredThetaHEdgeCos(uint j) {
  const float u = float(j) / float(kMerlThetaHBins);
  return cos(u * u * 0.5 * kPi);
}

vec3 measuredEval(float file, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  const vec3 h = normalize(wi + wo);  // wi.z + wo.z > 0: never zero
  const float sinH = length(h.xy);
  // atan rather than acos: acos(h.z) loses the small angles the non-linear axis resolves finely.
  const float thetaH = atan(sinH, h.z);
  // wi turned by -phi_h about n, then by -theta_h about the bitangent (the database's reader).
  const vec2 cs = sinH > 0.0 ? h.xy / sinH : vec2(1.0, 0.0);
  const vec3 turned = vec3(wi.x * cs.x + wi.y * cs.y, wi.y * cs.x - wi.x * cs.y, wi.z);
  const vec3 diff = vec3(turned.x * h.z - turned.z * sinH, turned.y, turned.x * sinH + turned.z * h.z);
  const float thetaD = atan(length(diff.xy), diff.z);
  float phiD = atan(diff.y, diff.x);
  if (phiD < 0.0) phiD += kPi;  // reciprocity: phi_d and phi_d + pi are the same pair
  const uint ih = measuredThetaHBin(thetaH);
  const uint id = uint(clamp(thetaD / (0.5 * kPi) * float(kMerlThetaDBins), 0.0, float(kMerlThetaDBins - 1)));
  const uint ip = uint(clamp(phiD / kPi * float(kMerlPhiDBins), 0.0, float(kMerlPhiDBins - 1)));
  const uint at = measuredBlock(file) + kMeasuredValues + 3u * (ip + kMerlPhiDBins * (id + kMerlThetaDBins * ih));
  return vec3(brdfTables[at], brdfTables[at + 1u], brdfTables[at + 2u]);
}

// Density of the half vector h per unit solid angle: linear in cos theta_h between the edges of its bin.
float measuredHalfVectorPdf(uint block, vec3 h) {
  const uint j = measuredThetaHBin(atan(length(h.xy), h.z));
  const float c0 = measuredThetaHEdgeCos(j), c1 = measuredThetaHEdgeCos(j + 1u);
  const float t = c0 > c1 ? clamp((c0 - h.z) / (c0 - c1), 0.0, 1.0) : 0.0;
  const float a = brdfTables[block + kMeasuredDensity + j], b = brdfTables[block + kMeasuredDensity + j + 1u];
  return a + t * (b - a);
}

float measuredPdf(float file, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const uint block = measuredBlock(file);
  const float pCosine = brdfTables[block + kMeasuredCosineProbability];
  const vec3 h = normalize(wi + wo);
  // Reflecting wo about h divides the half vector's density by 4 (wo.h).
  return pCosine * cosineHemispherePdf(wi) + (1.0 - pCosine) * measuredHalfVectorPdf(block, h) / (4.0 * dot(wo, h));
}

BsdfSample measuredSample(float file, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const uint block = measuredBlock(file);
  vec3 wi;
  if (u.x < 1.0 - brdfTables[block + kMeasuredCosineProbability]) {
    // The first bin whose inclusive cdf exceeds u.y (binary search over the 90 entries).
    uint lo = 0u, hi = kMerlThetaHBins - 1u;
    while (lo < hi) {
      const uint mid = (lo + hi) / 2u;
      if (brdfTables[block + kMeasuredCdf + mid] > u.y) hi = mid;
      else lo = mid + 1u;
    }
    const float below = lo > 0u ? brdfTables[block + kMeasuredCdf + lo - 1u] : 0.0;
    const float pmf = brdfTables[block + kMeasuredPmf + lo];
    const float v = pmf > 0.0 ? clamp((u.y - below) / pmf, 0.0, 1.0) : 0.5;
    // t along cos theta_h from edge lo to lo + 1, density a (1 - t) + b t: the quadratic cdf's root without
    // cancellation.
    const float a = brdfTables[block + kMeasuredDensity + lo], b = brdfTables[block + kMeasuredDensity + lo + 1u];
    const float t = a + b > 0.0 ? v * (a + b) / (a + sqrt(max(0.0, a * a + v * (b * b - a * a)))) : v;
    const float c0 = measuredThetaHEdgeCos(lo);
    const float cosTheta = c0 + clamp(t, 0.0, 1.0) * (measuredThetaHEdgeCos(lo + 1u) - c0);
    const float sinTheta = sqrt(max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
    const float phi = kTwoPi * u.z;
    wi = reflectAbout(wo, vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta));
  } else {
    wi = sampleCosineHemisphere(u.yz);
  }
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, measuredEval(file, wi, wo), measuredPdf(file, wi, wo));
}

#endif
