// The half vector and the microfacet terms shared by the models, each from its components (docs/brdf_contract.md).
//   D_Beckmann:        Beckmann & Spizzichino, "The Scattering of Electromagnetic Waves from Rough Surfaces",
//                      1963, in the form of Cook & Torrance, "A Reflectance Model for Computer Graphics",
//                      ACM TOG 1(1), 1982.
//   G_TorranceSparrow: Torrance & Sparrow, "Theory for Off-Specular Reflection from Roughened Surfaces",
//                      JOSA 57(9), 1967, as written by Blinn, "Models of Light Reflection for Computer
//                      Synthesized Pictures", SIGGRAPH 1977, and Cook & Torrance 1982.
#ifndef RAYLAB_BRDF_MICROFACET_GLSL
#define RAYLAB_BRDF_MICROFACET_GLSL

#include "brdf/common.glsl"

// For unit wi, wo lifted off the horizon (liftOffHorizon): h = wi + wo with h.z >= 2e-15, so h.z^2 >= 4e-30
// and every ratio below is finite.
struct HalfVector {
  vec3 h;             // wi + wo, unnormalised
  float len;          // |h|, > 0
  float tan2Theta;    // (h_x^2 + h_y^2) / h_z^2 from the components: no acos, no 1 - cos^2 (both lose all
                      // accuracy in float32 for m <= 0.01); at most 4 / 4e-30 = 1e30
  float NoH;          // h_z / |h|
  float VoH;          // V.H = L.H = (wo.h)/|h| = |h|/2, since |h|^2 = 2 + 2 wi.wo = 2 wo.h for unit vectors;
                      // unlike 1 + wi.wo it does not round to 0 when wi is nearly -wo
  float oneMinusVoH;  // 1 - |h|/2 = |wi - wo|^2 / (2 (2 + |h|)), as |wi + wo|^2 + |wi - wo|^2 = 4: no cancellation
};

HalfVector halfVector(vec3 wi, vec3 wo) {
  HalfVector hv;
  hv.h = wi + wo;
  hv.len = length(hv.h);
  hv.tan2Theta = dot(hv.h.xy, hv.h.xy) / (hv.h.z * hv.h.z);
  hv.NoH = hv.h.z / hv.len;
  hv.VoH = 0.5 * hv.len;
  const vec3 d = wi - wo;
  hv.oneMinusVoH = dot(d, d) / (2.0 * (2.0 + hv.len));
  return hv;
}

// Beckmann D = exp(-tan^2 / m^2) / (pi m^2 cos^4), with 1/cos^4 = (1 + tan^2)^2.
float D_Beckmann(float tan2Theta, float m) {
  const float m2 = m * m;
  const float x = tan2Theta / m2;
  // Beyond this exp(-x) < 1.2e-38 and D < 1e-32 for every m in [0.001, 1]; stopping here also keeps
  // (1 + tan^2)^2 from overflowing when tan^2 is near 1e30.
  if (x > kExpUnderflow) return 0.0;
  const float secant2 = 1.0 + tan2Theta;
  return exp(-x) * secant2 * secant2 / (kPi * m2);
}

// G = min(1, 2 (N.H)(N.V) / (V.H), 2 (N.H)(N.L) / (V.H)); V.H >= h_z / 2 >= 1e-15, so no division by 0.
float G_TorranceSparrow(float NoH, float NoV, float NoL, float VoH) {
  return min(1.0, 2.0 * NoH * min(NoV, NoL) / VoH);
}

#endif
