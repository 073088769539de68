// glTF 2.0 metallic-roughness (The Khronos Group, "glTF 2.0 Specification", Appendix B), as its formulas read:
// D in N.H, the height-correlated visibility Vis in the cosines, Schlick's Fresnel in VH = |wo.H|; with
// KHR_materials_specular's dielectric_f0 = min(f0 specularColor, 1) specular and dielectric_f90 = specular, and
// its dielectric BRDF F spec + (1 - max(F)) diffuse, as the extension's text writes them.
#include <algorithm>
#include <cmath>

#include "generated/reference_params.h"
#include "reference/ggx.h"
#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {
namespace {

double alphaOf(const GltfPbrParams& p) { return std::max(p.roughness * p.roughness, 1e-3); }
dvec3 dielectricF0(const GltfPbrParams& p) {
  const double f0 = (p.ior - 1.0) * (p.ior - 1.0) / ((p.ior + 1.0) * (p.ior + 1.0));
  return glm::min(f0 * p.specular_color, dvec3(1.0)) * p.specular;
}

}  // namespace

Lobes gltfPbrEval(const GltfPbrParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  const double alpha = alphaOf(p), a2 = alpha * alpha;
  const dvec3 H = glm::normalize(wi + wo);
  const double NoH = H.z;
  const double VH = std::abs(glm::dot(wo, H));
  const double denominator = NoH * NoH * (a2 - 1.0) + 1.0;
  const double D = a2 / (kPi * denominator * denominator);
  const double vis = 0.5 / (wi.z * std::sqrt(wo.z * wo.z * (1.0 - a2) + a2) + wo.z * std::sqrt(wi.z * wi.z * (1.0 - a2) + a2));
  const dvec3 f0 = dielectricF0(p);
  const double w = std::pow(1.0 - VH, 5.0);
  const dvec3 Fd = f0 + (dvec3(p.specular) - f0) * w;
  const double FdMax = std::max({Fd.r, Fd.g, Fd.b});
  const dvec3 Fm = F_Schlick(p.base_color, VH);
  const dvec3 diffuse = (1.0 - p.metallic) * (1.0 - FdMax) * p.base_color * kInvPi;
  const dvec3 specular = ((1.0 - p.metallic) * Fd + p.metallic * Fm) * (vis * D);
  return {diffuse, specular};
}

dvec3 gltfPbrSampleSpecular(const GltfPbrParams& p, const dvec3& wo, const dvec2& u) {
  const double alpha = alphaOf(p);
  return reflectAbout(wo, sampleGgxVisibleNormal(wo, alpha, alpha, u));
}

double gltfPbrPdfSpecular(const GltfPbrParams& p, const dvec3& wi, const dvec3& wo) {
  const double alpha = alphaOf(p);
  return ggxReflectionPdf(wi + wo, wo, alpha, alpha);
}

// The mixture weighs the diffuse albedo (1 - metallic) base_color against the specular F0.
SpecularLobe gltfPbrSpecularLobe(const GltfPbrParams& p) {
  const dvec3 specularF0 = glm::mix(dielectricF0(p), p.base_color, p.metallic);
  return {mixtureProbability((1.0 - p.metallic) * p.base_color, specularF0), dvec2(alphaOf(p)), false};
}

}  // namespace raylab::reference
