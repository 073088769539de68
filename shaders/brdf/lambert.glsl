// Lambert: the ideal diffuse reflector.
// | parameter | range  | default | meaning            |
// | rho_d     | [0, 1] | 0.5     | diffuse albedo RGB |
// Lambert, "Photometria", 1760; f = rho_d / pi (../shared/BRDF_SPEC.md).
#ifndef RAYLAB_BRDF_LAMBERT_GLSL
#define RAYLAB_BRDF_LAMBERT_GLSL

#include "brdf/common.glsl"

vec3 lambertEval(vec3 rhoD, vec3 wi, vec3 wo) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  return rhoD * kInvPi;
}

#endif
