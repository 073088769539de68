// The reference's dispatch over the models and the lobe mixture of the sampler (docs/brdfs.md, "Sampling").
#include <cmath>

#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "reference/sampling.h"

namespace raylab::reference {

bool aboveHorizon(const dvec3& wi, const dvec3& wo) {
  // Written so that NaN fails it: the contract's f = 0 when cos_i <= 0 or cos_o <= 0.
  return wi.z > 0.0 && wo.z > 0.0 && std::isfinite(wi.x) && std::isfinite(wi.y) && std::isfinite(wi.z) &&
         std::isfinite(wo.x) && std::isfinite(wo.y) && std::isfinite(wo.z);
}

Lobes evalLobes(const Material& material, const dvec3& wi, const dvec3& wo) {
  switch (material.model) {
    case gpu::kModelLambert: return lambertEval(material, wi, wo);
    case gpu::kModelPhong: return phongEval(material, wi, wo);
    case gpu::kModelBlinnPhong: return blinnPhongEval(material, wi, wo);
    case gpu::kModelCookTorrance: return cookTorranceEval(material, wi, wo);
    case gpu::kModelWard: return wardEval(material, wi, wo);
    case gpu::kModelWardDuer: return wardDuerEval(material, wi, wo);
    case gpu::kModelWardGmd: return wardGmdEval(material, wi, wo);
    case gpu::kModelAshikhminShirley: return ashikhminShirleyEval(material, wi, wo);
    default: return {};  // glass: a delta BSDF has no finite f
  }
}

dvec3 eval(const Material& material, const dvec3& wi, const dvec3& wo) {
  return evalLobes(material, wi, wo).sum();
}

dvec3 sampleSpecular(const Material& material, const dvec3& wo, const dvec2& u) {
  switch (material.model) {
    case gpu::kModelPhong: return phongSampleSpecular(material, wo, u);
    case gpu::kModelBlinnPhong: return blinnPhongSampleSpecular(material, wo, u);
    case gpu::kModelCookTorrance: return cookTorranceSampleSpecular(material, wo, u);
    case gpu::kModelWard:
    case gpu::kModelWardDuer:
    case gpu::kModelWardGmd: return wardSampleSpecular(material, wo, u);
    case gpu::kModelAshikhminShirley: return ashikhminShirleySampleSpecular(material, wo, u);
    default: return dvec3(0.0);
  }
}

double pdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo) {
  switch (material.model) {
    case gpu::kModelPhong: return phongPdfSpecular(material, wi, wo);
    case gpu::kModelBlinnPhong: return blinnPhongPdfSpecular(material, wi, wo);
    case gpu::kModelCookTorrance: return cookTorrancePdfSpecular(material, wi, wo);
    case gpu::kModelWard:
    case gpu::kModelWardDuer:
    case gpu::kModelWardGmd: return wardPdfSpecular(material, wi, wo);
    case gpu::kModelAshikhminShirley: return ashikhminShirleyPdfSpecular(material, wi, wo);
    default: return 0.0;
  }
}

double specularProbability(const Material& material) {
  if (material.model == gpu::kModelLambert || material.model == gpu::kModelGlass) return 0.0;
  // Rd and Rs of ashikhmin_shirley live in rhoD and rhoS.
  const double diffuse = material.rhoD.x + material.rhoD.y + material.rhoD.z;
  const double specular = material.rhoS.x + material.rhoS.y + material.rhoS.z;
  // Both zero: f = 0 and either lobe serves; the contract fixes 0.5 (and the division needs a non-zero sum).
  if (!(diffuse + specular > 0.0)) return 0.5;
  return specular / (diffuse + specular);
}

double pdf(const Material& material, const dvec3& wi, const dvec3& wo) {
  if (material.model == gpu::kModelGlass || !aboveHorizon(wi, wo)) return 0.0;
  const double pSpec = specularProbability(material);
  double density = (1.0 - pSpec) * pdfCosineHemisphere(wi);
  if (pSpec > 0.0) density += pSpec * pdfSpecular(material, wi, wo);
  return density;
}

Sample sample(const Material& material, const dvec3& wo, const dvec3& u) {
  // aboveHorizon(wo, wo): wo alone must be finite and above the horizon.
  if (material.model == gpu::kModelGlass || !aboveHorizon(wo, wo)) return {};
  // u.x only picks the lobe; the direction uses (u.y, u.z), so that both lobes see uniform numbers.
  const dvec2 uDirection(u.y, u.z);
  const dvec3 wi = u.x < specularProbability(material) ? sampleSpecular(material, wo, uDirection)
                                                       : sampleCosineHemisphere(uDirection);
  if (!aboveHorizon(wi, wo)) return {};  // at or below the horizon: a failed sample
  return {wi, eval(material, wi, wo), pdf(material, wi, wo)};
}

}  // namespace raylab::reference
