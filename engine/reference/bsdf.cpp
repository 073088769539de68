// The reference's dispatch over the models and the lobe mixture of the sampler (docs/brdfs.md, "Sampling").
#include <cmath>

#include "reference/brdf_reference.h"
#include "reference/models.h"
#include "reference/sampling.h"
#include "shared/brdf_lobes.h"

namespace raylab::reference {

bool aboveHorizon(const dvec3& wi, const dvec3& wo) {
  // Written so that NaN fails it: the contract's f = 0 when cos_i <= 0 or cos_o <= 0.
  return wi.z > 0.0 && wo.z > 0.0 && std::isfinite(wi.x) && std::isfinite(wi.y) && std::isfinite(wi.z) &&
         std::isfinite(wo.x) && std::isfinite(wo.y) && std::isfinite(wo.z);
}

bool finiteAndOffTheSurface(const dvec3& w) {
  return w.z != 0.0 && std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z);
}

dvec3 eval(const Material& material, const dvec3& wi, const dvec3& wo) {
  return evalLobes(material, wi, wo).sum();
}

double mixtureProbability(const dvec3& diffuse, const dvec3& specular) {
  const double d = diffuse.x + diffuse.y + diffuse.z;
  const double s = specular.x + specular.y + specular.z;
  // Both zero: f = 0 and either lobe serves; the contract fixes 0.5 (and the division needs a non-zero sum).
  if (!(d + s > 0.0)) return 0.5;
  return s / (d + s);
}

double specularProbability(const Material& material) {
  const std::optional<SpecularLobe> lobe = specularLobe(material);
  return lobe ? lobe->probability : 0.0;
}

namespace {

// A delta BSDF has neither f nor a density (its directions come from deltaEvent).
bool hasDensity(const Material& material) {
  return (lobeFlags(material) & (gpu::kLobeDiffuse | gpu::kLobeGlossy)) != 0;
}

}  // namespace

double pdf(const Material& material, const dvec3& wi, const dvec3& wo) {
  if (const std::optional<double> twoSided = pdfTwoSided(material, wi, wo)) {
    return finiteAndOffTheSurface(wi) && finiteAndOffTheSurface(wo) ? *twoSided : 0.0;
  }
  if (!hasDensity(material) || !aboveHorizon(wi, wo)) return 0.0;
  const double pSpec = specularProbability(material);
  double density = (1.0 - pSpec) * pdfCosineHemisphere(wi);
  if (pSpec > 0.0) density += pSpec * pdfSpecular(material, wi, wo);
  return density;
}

Sample sample(const Material& material, const dvec3& wo, const dvec3& u) {
  if (finiteAndOffTheSurface(wo)) {
    if (const std::optional<dvec3> wi = sampleTwoSided(material, wo, u)) {
      // A sample is valid only in the hemisphere of the lobe it chose; the model returns zero otherwise.
      const double density = pdf(material, *wi, wo);
      if (!finiteAndOffTheSurface(*wi) || !(density > 0.0)) return {};
      return {*wi, eval(material, *wi, wo), density};
    }
  }
  // aboveHorizon(wo, wo): wo alone must be finite and above the horizon.
  if (!hasDensity(material) || !aboveHorizon(wo, wo)) return {};
  // u.x only picks the lobe; the direction uses (u.y, u.z), so that both lobes see uniform numbers.
  const dvec2 uDirection(u.y, u.z);
  const dvec3 wi = u.x < specularProbability(material) ? sampleSpecular(material, wo, uDirection)
                                                       : sampleCosineHemisphere(uDirection);
  if (!aboveHorizon(wi, wo)) return {};  // at or below the horizon: a failed sample
  return {wi, eval(material, wi, wo), pdf(material, wi, wo)};
}

}  // namespace raylab::reference
