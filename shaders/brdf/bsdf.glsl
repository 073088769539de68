// The one dispatch over the BRDF library, in the local shading frame (z = shading normal; wi towards the
// light, wo towards the viewer). f excludes the cosine: the caller multiplies by cos_i. Every model is
// one-sided (0 when wi.z <= 0 or wo.z <= 0) and never NaN, Inf or negative for parameters in the ranges
// of engine/scene/material_params.cpp. Glass is a delta BSDF: 0 here, see glassEvent.
#ifndef RAYLAB_BRDF_BSDF_GLSL
#define RAYLAB_BRDF_BSDF_GLSL

#include "shared/scene_records.h"

#include "brdf/ashikhmin_shirley.glsl"
#include "brdf/blinnphong.glsl"
#include "brdf/cooktorrance.glsl"
#include "brdf/glass.glsl"
#include "brdf/lambert.glsl"
#include "brdf/phong.glsl"
#include "brdf/ward.glsl"
#include "brdf/ward_duer.glsl"
#include "brdf/ward_gmd.glsl"

vec3 bsdfEval(MaterialRecord material, vec3 wi, vec3 wo) {
  switch (material.model) {
    case kModelLambert:
      return lambertEval(material.rhoD, wi, wo);
    case kModelPhong:
      return phongEval(material.rhoD, material.rhoS, material.s, wi, wo);
    case kModelBlinnPhong:
      return blinnPhongEval(material.rhoD, material.rhoS, material.s, wi, wo);
    case kModelCookTorrance:
      return cookTorranceEval(material.rhoD, material.rhoS, material.m, material.eta, wi, wo);
    case kModelWard:
      return wardEval(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wi, wo);
    case kModelWardDuer:
      return wardDuerEval(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wi, wo);
    case kModelWardGmd:
      return wardGmdEval(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wi, wo);
    case kModelAshikhminShirley:
      return ashikhminShirleyEval(material.rhoD, material.rhoS, material.nu, material.nv, wi, wo);
    default:  // glass (delta) and unknown ids
      return vec3(0.0);
  }
}

// Density per unit solid angle of bsdfSample's direction: (1 - pSpec) cos_i / pi + pSpec pdfSpec.
float bsdfPdf(MaterialRecord material, vec3 wi, vec3 wo) {
  switch (material.model) {
    case kModelLambert:
      return lambertPdf(wi, wo);
    case kModelPhong:
      return phongPdf(material.rhoD, material.rhoS, material.s, wi, wo);
    case kModelBlinnPhong:
      return blinnPhongPdf(material.rhoD, material.rhoS, material.s, wi, wo);
    case kModelCookTorrance:
      return cookTorrancePdf(material.rhoD, material.rhoS, material.m, wi, wo);
    case kModelWard:
    case kModelWardDuer:
    case kModelWardGmd:
      return wardPdf(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wi, wo);
    case kModelAshikhminShirley:
      return ashikhminShirleyPdf(material.rhoD, material.rhoS, material.nu, material.nv, wi, wo);
    default:
      return 0.0;
  }
}

// u: three uniform numbers in [0, 1); u.x picks the lobe, (u.y, u.z) place the direction. A sample with
// pdf 0 failed (wo or the sampled direction at or below the horizon); otherwise f = bsdfEval(wi, wo) and
// pdf = bsdfPdf(wi, wo).
BsdfSample bsdfSample(MaterialRecord material, vec3 wo, vec3 u) {
  switch (material.model) {
    case kModelLambert:
      return lambertSample(material.rhoD, wo, u);
    case kModelPhong:
      return phongSample(material.rhoD, material.rhoS, material.s, wo, u);
    case kModelBlinnPhong:
      return blinnPhongSample(material.rhoD, material.rhoS, material.s, wo, u);
    case kModelCookTorrance:
      return cookTorranceSample(material.rhoD, material.rhoS, material.m, material.eta, wo, u);
    case kModelWard:
      return wardSample(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wo, u);
    case kModelWardDuer:
      return wardDuerSample(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wo, u);
    case kModelWardGmd:
      return wardGmdSample(material.rhoD, material.rhoS, material.alphaX, material.alphaY, wo, u);
    case kModelAshikhminShirley:
      return ashikhminShirleySample(material.rhoD, material.rhoS, material.nu, material.nv, wo, u);
    default:
      return noSample();
  }
}

// Probability that bsdfSample picks the specular lobe: 0 for lambert and glass.
float bsdfSpecularProbability(MaterialRecord material) {
  switch (material.model) {
    case kModelLambert:
    case kModelGlass:
      return 0.0;
    default:
      return specularProbability(material.rhoD, material.rhoS);
  }
}

#endif
