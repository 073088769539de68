// Constants and float32 helpers shared by the BRDF library. GLSL's log and pow are only specified to an
// absolute error of 2^-21 near 1 (Vulkan spec, "Precision and Operation of SPIR-V Instructions"), which
// ruins (N.H)^s for s = 10^4; the lobes are therefore written as exp(s * log1p(...)) with the accurate
// log1p below, computed from quantities that carry no cancellation.
#ifndef RAYLAB_BRDF_COMMON_GLSL
#define RAYLAB_BRDF_COMMON_GLSL

const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kTwoPi = 6.28318530717958647693;

// exp(-x) is below the smallest normal float (1.18e-38) for x > 87.3: a term carrying that factor is 0.
const float kExpUnderflow = 87.0;

// The one-sided models see directions at least kMinCos above the horizon (liftOffHorizon).
const float kMinCos = 1e-15;

// Directions in (0, kMinCos) above the horizon are lifted to kMinCos. This moves a unit vector by at most
// 1e-15 rad, far below the float32 resolution of its components (6e-8), and keeps every product and square
// of cosines (>= 1e-30) and every term built from them inside the float range. f is therefore accurate for
// cosines >= 1e-15 and finite below (where the exact value of the sharpest lobes exceeds 3.4e38 anyway).
vec3 liftOffHorizon(vec3 w) { return vec3(w.xy, max(w.z, kMinCos)); }

// 2 atanh(z) / z - 1 for z = x / (2 + x), i.e. the series of log1p(x) = 2 (z + z^3/3 + z^5/5 + ...):
// with |z| <= 1/3 the terms after z^15/15 are below 3e-9 relative.
float log1pSeries(float z2) {
  return z2 * (1.0 / 3.0 + z2 * (1.0 / 5.0 + z2 * (1.0 / 7.0 + z2 * (1.0 / 9.0 + z2 * (1.0 / 11.0 +
         z2 * (1.0 / 13.0 + z2 * (1.0 / 15.0)))))));
}

// log(1 + x) for x > -1, accurate to a few ulps everywhere (log itself is accurate away from 1).
float log1pAccurate(float x) {
  if (x > -0.5 && x < 1.0) {
    const float z = x / (2.0 + x);
    return 2.0 * z * (1.0 + log1pSeries(z * z));
  }
  return log(1.0 + x);  // 1 + x is exact for x in [-1, -0.5] and rounds by half an ulp above 1
}

// log(1 + x) / x for x >= 0, equal to 1 at x = 0 (its limit), without dividing by a small x.
float log1pOverX(float x) {
  if (x < 1.0) {
    const float z = x / (2.0 + x);
    return 2.0 / (2.0 + x) * (1.0 + log1pSeries(z * z));
  }
  return log(1.0 + x) / x;
}

// exp(x) - 1 without the cancellation of exp(x) - 1 near 0: Taylor series below 1/2 in size (the first omitted
// term is 0.5^10/10! = 3e-10 relative).
float expm1Accurate(float x) {
  if (abs(x) < 0.5) {
    return x * (1.0 + x * (1.0 / 2.0 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 + x * (1.0 / 720.0 +
           x * (1.0 / 5040.0 + x * (1.0 / 40320.0 + x * (1.0 / 362880.0)))))))));
  }
  return exp(x) - 1.0;
}

// expm1(x) / x, 1 at x = 0 (its limit), without dividing by a small x: the series below 1e-3 in size.
float expm1OverX(float x) { return abs(x) < 1.0e-3 ? 1.0 + x * (0.5 + x / 6.0) : expm1Accurate(x) / x; }

float pow5(float x) {
  const float x2 = x * x;
  return x2 * x2 * x;
}

float sum3(vec3 v) { return v.x + v.y + v.z; }

#endif
