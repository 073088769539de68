// Importance sampling shared by the models: the sample record, the lobe choice, the cosine-weighted
// hemisphere and the power-cosine lobes. The strategy (which u drives what) is fixed in docs/brdfs.md so
// that this library and the CPU reference implement the same pdf.
#ifndef RAYLAB_BRDF_SAMPLING_GLSL
#define RAYLAB_BRDF_SAMPLING_GLSL

#include "brdf/common.glsl"
#include "common/frame.glsl"

// A sampled incident direction in the local frame with f(wi, wo) and the pdf of the whole sampling
// strategy (per unit solid angle). pdf 0: the sample failed and carries no direction.
struct BsdfSample {
  vec3 wi;
  vec3 f;
  float pdf;
};

BsdfSample noSample() { return BsdfSample(vec3(0.0), vec3(0.0), 0.0); }

// A direction becomes a sample only above the horizon, and only with a positive pdf (a pdf that underflows
// to 0 would make f / pdf infinite).
BsdfSample acceptSample(vec3 wi, vec3 f, float pdf) {
  if (!(wi.z > 0.0 && pdf > 0.0)) return noSample();
  return BsdfSample(wi, f, pdf);
}

// Probability of sampling the specular lobe: its share of the summed RGB reflectances; 0.5 when both are 0
// (f = 0 then, and the share would be 0/0).
float specularProbability(vec3 diffuse, vec3 specular) {
  const float d = sum3(diffuse);
  const float s = sum3(specular);
  return d + s > 0.0 ? s / (d + s) : 0.5;
}

// Shirley & Chiu, "A Low Distortion Map Between Disk and Square", JGT 2(3), 1997: [0,1)^2 to the unit disk.
// Returns (x, y) and the radius r.
vec3 sampleConcentricDisk(vec2 u) {
  const vec2 a = 2.0 * u - 1.0;
  if (a.x == 0.0 && a.y == 0.0) return vec3(0.0);  // the centre, where both ratios below would be 0/0
  float r, phi;
  if (abs(a.x) > abs(a.y)) {
    r = a.x;
    phi = (0.25 * kPi) * (a.y / a.x);
  } else {
    r = a.y;
    phi = 0.5 * kPi - (0.25 * kPi) * (a.x / a.y);
  }
  return vec3(r * cos(phi), r * sin(phi), abs(r));
}

// Malley's method: a uniform disk point lifted to the hemisphere is cosine-distributed, pdf = cos / pi.
// z = sqrt((1 - r)(1 + r)) rather than sqrt(1 - x^2 - y^2), which cancels near the rim.
vec3 sampleCosineHemisphere(vec2 u) {
  const vec3 disk = sampleConcentricDisk(u);
  return vec3(disk.xy, sqrt((1.0 - disk.z) * (1.0 + disk.z)));  // r = max(|a.x|, |a.y|) <= 1: never negative
}

float cosineHemispherePdf(vec3 wi) { return wi.z * kInvPi; }

// (cos, sin) of an angle whose cosine is v^(1 / exponentPlusOne), the inversion of the density
// proportional to cos^exponent over the hemisphere. With L = log(v) / (exponent + 1): cos = exp(L) and
// sin^2 = -expm1(2L), which keeps sin accurate for exponents of 10^4 (1 - cos^2 would be noise).
vec2 powerCosine(float v, float exponentPlusOne) {
  if (v <= 0.0) return vec2(0.0, 1.0);  // the limit v -> 0, where log(v) is -infinity
  const float L = log1pAccurate(v - 1.0) / exponentPlusOne;  // v - 1 is exact for v in [0.5, 1)
  // L <= 0, so -expm1(2L) >= 0; the max only absorbs a rounding of -0.
  return vec2(exp(L), sqrt(max(0.0, -expm1Accurate(2.0 * L))));
}

// The unit vector at angle (cosAlpha, sinAlpha) from the unit axis, at azimuth phi around it.
vec3 aroundAxis(vec3 axis, float cosAlpha, float sinAlpha, float phi) {
  const vec3 t = anyTangent(axis);
  const vec3 b = cross(axis, t);
  return cosAlpha * axis + sinAlpha * (cos(phi) * t + sin(phi) * b);
}

// Mirror wo about the unit half vector H.
vec3 reflectAbout(vec3 wo, vec3 H) { return 2.0 * dot(wo, H) * H - wo; }

#endif
