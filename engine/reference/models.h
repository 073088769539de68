// The per-model functions of the reference, named as in the GLSL (<model>Eval, ...). Each model's f is a
// diffuse term plus a specular term; the reference keeps the two apart (Lobes) so that the albedo quadrature
// can integrate each in coordinates that suit it. eval() of brdf_reference.h is their sum.
//
// Every function here works in the local shading frame (z = n) on unit wi, wo; the <model>Eval functions
// return exactly zero unless wi.z > 0 and wo.z > 0 (and both are finite).
#pragma once

#include <glm/glm.hpp>

#include "reference/brdf_reference.h"

namespace raylab::reference {

struct Lobes {
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};
  dvec3 sum() const { return diffuse + specular; }
};

// The one-sidedness guard of the contract: both directions strictly above the horizon. NaN fails it.
bool aboveHorizon(const dvec3& wi, const dvec3& wo);

Lobes lambertEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes phongEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes blinnPhongEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes cookTorranceEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes wardEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes wardDuerEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes wardGmdEval(const Material& material, const dvec3& wi, const dvec3& wo);
Lobes ashikhminShirleyEval(const Material& material, const dvec3& wi, const dvec3& wo);
// Dispatch on material.model; zero for glass (a delta BSDF).
Lobes evalLobes(const Material& material, const dvec3& wi, const dvec3& wo);

// The specular lobe's sampler (u = (u.y, u.z) of the sample triple; the returned direction may lie below the
// horizon, which makes the sample fail) and its density per unit solid angle of wi, for wi and wo above the
// horizon. The strategies are those of the shared brief (docs/brdfs.md, "Sampling"). The ward sampler is
// shared by ward, ward_duer and ward_gmd.
dvec3 phongSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double phongPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
dvec3 blinnPhongSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double blinnPhongPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
dvec3 cookTorranceSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double cookTorrancePdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
dvec3 wardSampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double wardPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
dvec3 ashikhminShirleySampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double ashikhminShirleyPdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
// Dispatch; lambert and glass have no specular lobe (direction 0, density 0).
dvec3 sampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double pdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);

}  // namespace raylab::reference
