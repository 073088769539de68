// The one dispatch over the BRDF library, in the local shading frame (z = shading normal; wi towards the
// light, wo towards the viewer). f excludes the cosine: the caller multiplies by |cos_i|. Every model is
// one-sided (0 when wi.z <= 0 or wo.z <= 0) except the two-sided ones (isTwoSided: rough glass), and never NaN,
// Inf or negative for parameters in the ranges of its table. A delta BSDF (glass) is 0 here: see bsdfSampleSpecular and the lobe flags (bsdfFlags) below.
// The per-model branches are generated from the model registry (generated/bsdf_models.glsl, written by
// tools/cmake/brdf_registry.py from shaders/brdf/models.cmake and each model's parameter table).
#ifndef RAYLAB_BRDF_BSDF_GLSL
#define RAYLAB_BRDF_BSDF_GLSL

#include "shared/brdf_lobes.h"
#include "shared/scene_records.h"

#include "common/specialization.glsl"

#include "brdf/delta_event.glsl"
#include "brdf/sampling.glsl"

#include "generated/bsdf_models.glsl"

vec3 bsdfEval(MaterialRecord m, vec3 wi, vec3 wo) { return modelEval(m, wi, wo); }

// Density per unit solid angle of bsdfSample's direction.
float bsdfPdf(MaterialRecord m, vec3 wi, vec3 wo) { return modelPdf(m, wi, wo); }

// u: three uniform numbers in [0, 1); u.x picks the lobe, (u.y, u.z) place the direction. A sample with
// pdf 0 failed (wo or the sampled direction at or below the horizon); otherwise f = bsdfEval(wi, wo) and
// pdf = bsdfPdf(wi, wo).
BsdfSample bsdfSample(MaterialRecord m, vec3 wo, vec3 u) { return modelSample(m, wo, u); }

// The lobe flags the model declares (shared/brdf_lobes.h).
uint bsdfFlags(MaterialRecord m) { return modelFlags(m.model); }

// The absorption coefficient per unit length inside a transmissive material with a volume (openpbr's
// transmission_depth > 0); zero for every other material. The path integrator attenuates the segments inside by it.
vec3 bsdfMediumAbsorption(MaterialRecord m) { return modelMediumAbsorption(m); }

// True for a BSDF of delta lobes only (glass): bsdfEval, bsdfPdf and light sampling see nothing of it.
bool isSpecularOnly(uint flags) { return (flags & (kLobeDiffuse | kLobeGlossy)) == 0u; }

// True for transmission with a density (rough glass): wi and wo may lie on either side of the normal, and f,
// its density and its samples are defined on both (the integrators shade it in the outward normal's frame).
bool isTwoSided(uint flags) { return (flags & kLobeTransmission) != 0u && !isSpecularOnly(flags); }

struct SpecularSample {
  vec3 wi;       // unit; zero when there is none
  vec3 weight;   // f cos / probability: what the throughput is multiplied by
  uint flags;    // kLobeSpecular and kLobeReflection or kLobeTransmission
};

// The delta lobes of a specular-only BSDF (glass) for the direction wo, in any frame with n its outward shading
// normal: both directions, the Fresnel term of the kernel variant (exact, or Schlick's: the other one's
// arithmetic is dead code and compiles away), total internal reflection and the transmittance on the way in.
// The slides' integrator follows both lobes (closest_hit.glsl), the path integrator one (bsdfSampleSpecular).
struct DeltaLobes {
  vec3 reflected;
  vec3 refracted;      // zero under total internal reflection
  float fresnel;
  bool tir;
  vec3 transmittance;
};

DeltaLobes bsdfDeltaLobes(MaterialRecord m, vec3 wo, vec3 n) {
  const DeltaEvent event = modelDeltaEvent(m, wo, n);
  const float fresnel = kGlassFresnel == kFresnelSchlick ? event.fresnelSchlick : event.fresnelExact;
  return DeltaLobes(event.reflected, event.refracted, fresnel, event.tir, event.transmittance);
}

// One of the delta lobes, chosen by u: reflection with probability delta + (1 - delta) F (1 under total internal
// reflection), else refraction, with the transmittance on the way in. The probabilities equal the weights, so
// the weight is 1 (or the transmittance).
SpecularSample bsdfSampleSpecular(MaterialRecord m, vec3 wo, vec3 n, float u) {
  const DeltaLobes lobes = bsdfDeltaLobes(m, wo, n);
  const float reflectProbability = lobes.tir ? 1.0 : m.delta + (1.0 - m.delta) * lobes.fresnel;
  if (u < reflectProbability) return SpecularSample(lobes.reflected, vec3(1.0), kLobeSpecular | kLobeReflection);
  const bool entering = dot(wo, n) >= 0.0;
  return SpecularSample(lobes.refracted, entering ? lobes.transmittance : vec3(1.0), kLobeSpecular | kLobeTransmission);
}

#endif
