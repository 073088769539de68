// The one dispatch over the BRDF library, in the local shading frame (z = shading normal; wi towards the
// light, wo towards the viewer). f excludes the cosine: the caller multiplies by cos_i. Every model is
// one-sided (0 when wi.z <= 0 or wo.z <= 0) and never NaN, Inf or negative for parameters in the ranges
// of engine/scene/material_params.cpp. Glass is a delta BSDF: 0 here, see glassEvent.
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

// Probability that bsdfSample picks the specular lobe: 0 for lambert and glass.
float bsdfSpecularProbability(MaterialRecord m) {
  return m.model == kModelLambert || m.model == kModelGlass ? 0.0 : specularProbability(m.rhoD, m.rhoS);
}

#endif
