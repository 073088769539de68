// Measured: a MERL BRDF database file (Matusik, Pfister, Brand & McMillan, "A Data-Driven Reflectance Model",
// SIGGRAPH 2003), looked up as the database's own reader does: Rusinkiewicz's half/difference angles, the
// non-linear theta_h axis, the nearest sample, missing samples 0 (docs/brdfs.md, "measured").
// lobes: reflection glossy
// | parameter | range          | default | kind | meaning                                              |
// |-----------|----------------|---------|------|------------------------------------------------------|
// | file      | [0, 16777215]  | 0       | file | the MERL .binary file, a path (relative to the scene) |
// Rusinkiewicz, "A New Change of Variables for Efficient BRDF Representation", EGWR 1998. Sampling: a half
// vector from the file's table over the theta_h bins (piecewise linear in cos theta_h), mixed with cosine-weighted
// directions (engine/measured/measured_sampling.h); the file's block of the BRDF tables is block number `file`.
#ifndef RAYLAB_BRDF_MEASURED_GLSL
#define RAYLAB_BRDF_MEASURED_GLSL

#include "brdf/half_vector_table.glsl"

vec3 measuredEval(float file, vec3 wi, vec3 wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return vec3(0.0);  // one-sided; also false for NaN directions
  float sinH, cosH;
  const vec3 diff = merlDifferenceVector(wi, wo, sinH, cosH);
  // atan rather than acos: acos(h.z) loses the small angles the non-linear axis resolves finely.
  const float thetaH = atan(sinH, cosH);
  const float thetaD = atan(length(diff.xy), diff.z);
  float phiD = atan(diff.y, diff.x);
  if (phiD < 0.0) phiD += kPi;  // reciprocity: phi_d and phi_d + pi are the same pair
  const uint ih = merlThetaHBin(thetaH);
  const uint id = uint(clamp(thetaD / (0.5 * kPi) * float(kMerlThetaDBins), 0.0, float(kMerlThetaDBins - 1)));
  const uint ip = uint(clamp(phiD / kPi * float(kMerlPhiDBins), 0.0, float(kMerlPhiDBins - 1)));
  const uint at = fileBlock(file) + kMeasuredValues + 3u * (ip + kMerlPhiDBins * (id + kMerlThetaDBins * ih));
  return vec3(brdfTables[at], brdfTables[at + 1u], brdfTables[at + 2u]);
}

float measuredPdf(float file, vec3 wi, vec3 wo) { return tablePdf(fileBlock(file) + kMeasuredSampler, wi, wo); }

BsdfSample measuredSample(float file, vec3 wo, vec3 u) {
  if (!(wo.z > 0.0)) return noSample();
  const vec3 wi = tableSampleDirection(fileBlock(file) + kMeasuredSampler, wo, u);
  if (!(wi.z > 0.0)) return noSample();
  return acceptSample(wi, measuredEval(file, wi, wo), measuredPdf(file, wi, wo));
}

#endif
