// Terms shared by Löw's two ABC models (abc_microfacet.glsl, abc_smooth.glsl): integrals of (1 + B x)^-C.
#ifndef RAYLAB_BRDF_ABC_GLSL
#define RAYLAB_BRDF_ABC_GLSL

#include "brdf/common.glsl"

// The integral of (1 + B x)^-C over x in [0, 1]: log(1 + B) expm1(s) / (s B) with s = (1 - C) log(1 + B).
float abcIntegral(float b, float c) {
  const float logB = log1pAccurate(b);
  return logB * expm1OverX((1.0 - c) * logB) / b;
}

// (1 + B x)^-C
float abcShape(float b, float c, float x) { return exp(-c * log1pAccurate(b * x)); }

#endif
