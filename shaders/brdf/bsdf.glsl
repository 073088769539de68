// The one dispatch over the BRDF library: evaluates the material's model in the local shading frame
// (z = shading normal). f excludes the cosine; the caller multiplies by cos_i.
#ifndef RAYLAB_BRDF_BSDF_GLSL
#define RAYLAB_BRDF_BSDF_GLSL

#include "brdf/lambert.glsl"

vec3 bsdfEval(MaterialRecord material, vec3 wi, vec3 wo) {
  switch (material.model) {
    case kModelLambert:
      return lambertEval(material.rhoD, wi, wo);
    default:
      return vec3(0.0);
  }
}

#endif
