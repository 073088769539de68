// The one dispatch over the BRDF library, in the local shading frame (z = shading normal; wi towards the
// light, wo towards the viewer). f excludes the cosine: the caller multiplies by cos_i. Every model is
// one-sided (0 when wi.z <= 0 or wo.z <= 0) and never NaN, Inf or negative for parameters in the ranges
// of engine/brdf_params/material_params.cpp. Glass is a delta BSDF: 0 here, see bsdfSampleSpecular and the lobe
// flags (bsdfFlags) below.
#ifndef RAYLAB_BRDF_BSDF_GLSL
#define RAYLAB_BRDF_BSDF_GLSL

#include "shared/scene_records.h"

#include "common/specialization.glsl"

#include "brdf/ashikhmin_shirley.glsl"
#include "brdf/blinnphong.glsl"
#include "brdf/cooktorrance.glsl"
#include "brdf/glass.glsl"
#include "brdf/lambert.glsl"
#include "brdf/phong.glsl"
#include "brdf/ward.glsl"
#include "brdf/ward_duer.glsl"
#include "brdf/ward_gmd.glsl"

// Every branch is guarded by modelEnabled (common/specialization.glsl): a kernel specialised for a scene
// keeps only the models the scene uses, and the driver removes the rest.

vec3 bsdfEval(MaterialRecord m, vec3 wi, vec3 wo) {
  const uint model = m.model;
  if (modelEnabled(kModelLambert) && model == kModelLambert) return lambertEval(m.rhoD, wi, wo);
  if (modelEnabled(kModelPhong) && model == kModelPhong) return phongEval(m.rhoD, m.rhoS, m.s, wi, wo);
  if (modelEnabled(kModelBlinnPhong) && model == kModelBlinnPhong) return blinnPhongEval(m.rhoD, m.rhoS, m.s, wi, wo);
  if (modelEnabled(kModelCookTorrance) && model == kModelCookTorrance) {
    return cookTorranceEval(m.rhoD, m.rhoS, m.m, m.eta, wi, wo);
  }
  if (modelEnabled(kModelWard) && model == kModelWard) return wardEval(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wi, wo);
  if (modelEnabled(kModelWardDuer) && model == kModelWardDuer) {
    return wardDuerEval(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wi, wo);
  }
  if (modelEnabled(kModelWardGmd) && model == kModelWardGmd) {
    return wardGmdEval(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wi, wo);
  }
  if (modelEnabled(kModelAshikhminShirley) && model == kModelAshikhminShirley) {
    return ashikhminShirleyEval(m.rhoD, m.rhoS, m.nu, m.nv, wi, wo);
  }
  return vec3(0.0);  // glass (a delta BSDF), models compiled out, unknown ids
}

bool isWard(uint model) { return model == kModelWard || model == kModelWardDuer || model == kModelWardGmd; }
bool anyWardEnabled() {
  return modelEnabled(kModelWard) || modelEnabled(kModelWardDuer) || modelEnabled(kModelWardGmd);
}

// Density per unit solid angle of bsdfSample's direction: (1 - pSpec) cos_i / pi + pSpec pdfSpec.
float bsdfPdf(MaterialRecord m, vec3 wi, vec3 wo) {
  const uint model = m.model;
  if (modelEnabled(kModelLambert) && model == kModelLambert) return lambertPdf(wi, wo);
  if (modelEnabled(kModelPhong) && model == kModelPhong) return phongPdf(m.rhoD, m.rhoS, m.s, wi, wo);
  if (modelEnabled(kModelBlinnPhong) && model == kModelBlinnPhong) return blinnPhongPdf(m.rhoD, m.rhoS, m.s, wi, wo);
  if (modelEnabled(kModelCookTorrance) && model == kModelCookTorrance) return cookTorrancePdf(m.rhoD, m.rhoS, m.m, wi, wo);
  if (anyWardEnabled() && isWard(model)) return wardPdf(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wi, wo);
  if (modelEnabled(kModelAshikhminShirley) && model == kModelAshikhminShirley) {
    return ashikhminShirleyPdf(m.rhoD, m.rhoS, m.nu, m.nv, wi, wo);
  }
  return 0.0;
}

// u: three uniform numbers in [0, 1); u.x picks the lobe, (u.y, u.z) place the direction. A sample with
// pdf 0 failed (wo or the sampled direction at or below the horizon); otherwise f = bsdfEval(wi, wo) and
// pdf = bsdfPdf(wi, wo).
BsdfSample bsdfSample(MaterialRecord m, vec3 wo, vec3 u) {
  const uint model = m.model;
  if (modelEnabled(kModelLambert) && model == kModelLambert) return lambertSample(m.rhoD, wo, u);
  if (modelEnabled(kModelPhong) && model == kModelPhong) return phongSample(m.rhoD, m.rhoS, m.s, wo, u);
  if (modelEnabled(kModelBlinnPhong) && model == kModelBlinnPhong) return blinnPhongSample(m.rhoD, m.rhoS, m.s, wo, u);
  if (modelEnabled(kModelCookTorrance) && model == kModelCookTorrance) {
    return cookTorranceSample(m.rhoD, m.rhoS, m.m, m.eta, wo, u);
  }
  if (modelEnabled(kModelWard) && model == kModelWard) return wardSample(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wo, u);
  if (modelEnabled(kModelWardDuer) && model == kModelWardDuer) {
    return wardDuerSample(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wo, u);
  }
  if (modelEnabled(kModelWardGmd) && model == kModelWardGmd) {
    return wardGmdSample(m.rhoD, m.rhoS, m.alphaX, m.alphaY, wo, u);
  }
  if (modelEnabled(kModelAshikhminShirley) && model == kModelAshikhminShirley) {
    return ashikhminShirleySample(m.rhoD, m.rhoS, m.nu, m.nv, wo, u);
  }
  return noSample();
}

// Lobe flags of a model and of a sample, as pbrt-v4's BxDFFlags: integrators ask these, never model ids.
const uint kLobeReflection = 1u;
const uint kLobeTransmission = 2u;
const uint kLobeDiffuse = 4u;
const uint kLobeGlossy = 8u;
const uint kLobeSpecular = 16u;  // a delta lobe: no density, only bsdfSampleSpecular produces its directions

uint bsdfFlags(MaterialRecord m) {
  if (featureEnabled(kFeatureGlass) && m.model == kModelGlass) {
    return kLobeReflection | kLobeTransmission | kLobeSpecular;
  }
  if (m.model == kModelLambert) return kLobeReflection | kLobeDiffuse;
  return kLobeReflection | kLobeDiffuse | kLobeGlossy;
}

// True for a BSDF of delta lobes only (glass): bsdfEval, bsdfPdf and light sampling see nothing of it.
bool isSpecularOnly(uint flags) { return (flags & (kLobeDiffuse | kLobeGlossy)) == 0u; }

struct SpecularSample {
  vec3 wi;       // unit; zero when there is none
  vec3 weight;   // f cos / probability: what the throughput is multiplied by
  uint flags;    // kLobeSpecular and kLobeReflection or kLobeTransmission
};

// One of the delta lobes of a specular-only BSDF, in any frame with n its outward shading normal, chosen by u.
// Glass is a smooth dielectric: reflection with probability delta + (1 - delta) F (1 under total internal
// reflection), else refraction, tinted on the way in. The probabilities equal the weights, so the weight is 1
// (or the tint).
SpecularSample bsdfSampleSpecular(MaterialRecord m, vec3 wo, vec3 n, float u) {
  const GlassEvent event = glassEvent(m.eta, wo, n);
  const float fresnel = kGlassFresnel == kFresnelSchlick ? event.fresnelSchlick : event.fresnelExact;
  const float reflectProbability = event.tir ? 1.0 : m.delta + (1.0 - m.delta) * fresnel;
  if (u < reflectProbability) return SpecularSample(event.reflected, vec3(1.0), kLobeSpecular | kLobeReflection);
  const bool entering = dot(wo, n) >= 0.0;
  return SpecularSample(event.refracted, entering ? m.tint : vec3(1.0), kLobeSpecular | kLobeTransmission);
}

#endif
