// GGX dielectric, rough glass (Walter et al., EGSR 2007), two-sided, as the contract writes it
// (docs/brdf_contract.md, "ggx_dielectric"): normalised half vectors, the textbook Fresnel equations with
// Snell's cosine, and the sampler of visible normals seen from wo followed by a Fresnel-weighted choice of
// reflection or refraction. Directions on either side of the outward normal z; eta_i, eta_o are the indices
// on the sides of wi and wo (1 outside, eta inside).
#include <cmath>

#include "generated/reference_params.h"
#include "reference/ggx.h"
#include "reference/terms.h"

namespace raylab::reference {
namespace {

bool finite(const dvec3& w) { return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z); }

// Exact F for light arriving at cosine cosI >= 0 from the medium etaI into etaT; 1 under total internal
// reflection.
double fresnel(double cosI, double etaI, double etaT) {
  const double ratio = etaI / etaT;
  const double sin2T = ratio * ratio * (1.0 - cosI * cosI);
  if (sin2T >= 1.0) return 1.0;
  return F_DielectricExact(etaI, etaT, cosI, std::sqrt(1.0 - sin2T));
}

double sideIndex(const dvec3& w, double eta) { return w.z > 0.0 ? 1.0 : eta; }

// The refraction half vector -(eta_i wi + eta_o wo), normalised and turned to the outside.
dvec3 transmissionHalfVector(double eta, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = glm::normalize(-(sideIndex(wi, eta) * wi + sideIndex(wo, eta) * wo));
  return h.z < 0.0 ? -h : h;
}

// Smith's separable G with each direction on the side of m that its own hemisphere requires.
double sidedG(const dvec3& m, const dvec3& wi, const dvec3& wo, double ax, double ay) {
  if (!(glm::dot(wi, m) * wi.z > 0.0 && glm::dot(wo, m) * wo.z > 0.0)) return 0.0;
  return G1_GGX(wi, ax, ay) * G1_GGX(wo, ax, ay);
}

// Fresnel's probability of reflection for the viewer wo at microfacet m, seen from wo's side.
double reflectProbability(double eta, const dvec3& m, const dvec3& wo) {
  const bool outside = wo.z > 0.0;
  return fresnel(std::abs(glm::dot(wo, m)), outside ? 1.0 : eta, outside ? eta : 1.0);
}

}  // namespace

Lobes ggxDielectricEval(const GgxDielectricParams& p, const dvec3& wi, const dvec3& wo) {
  if (!(wi.z != 0.0 && wo.z != 0.0 && finite(wi) && finite(wo))) return {};
  const double cosProduct = std::abs(wi.z * wo.z);
  if (wi.z * wo.z > 0.0) {
    const dvec3 H = (wo.z > 0.0 ? 1.0 : -1.0) * glm::normalize(wi + wo);
    const bool outside = wo.z > 0.0;
    const double F = fresnel(std::abs(glm::dot(wo, H)), outside ? 1.0 : p.eta, outside ? p.eta : 1.0);
    // G1 without the sidedness test, which unit directions on one side always pass (as ggx_conductor): for inputs
    // a rounding away from unit length it would only add a cut where wi is nearly -wo at grazing.
    const double G = G1_GGX(wi, p.alpha_x, p.alpha_y) * G1_GGX(wo, p.alpha_x, p.alpha_y);
    const double f = F * D_GGX(H, p.alpha_x, p.alpha_y) * G / (4.0 * cosProduct);
    return {dvec3(0.0), dvec3(f)};
  }
  const dvec3 H = transmissionHalfVector(p.eta, wi, wo);
  const double G = sidedG(H, wi, wo, p.alpha_x, p.alpha_y);
  if (!(G > 0.0)) return {};
  const double etaI = sideIndex(wi, p.eta), etaO = sideIndex(wo, p.eta);
  const double wiH = glm::dot(wi, H), woH = glm::dot(wo, H);
  // In exact arithmetic F is the same from either side; the outside direction's cosine is the accurate one.
  const double F = fresnel(std::abs(glm::dot(wi.z > 0.0 ? wi : wo, H)), 1.0, p.eta);
  const double denominator = etaI * wiH + etaO * woH;
  const double f = std::abs(wiH) * std::abs(woH) * etaO * etaO * (1.0 - F) * D_GGX(H, p.alpha_x, p.alpha_y) * G /
                   (cosProduct * denominator * denominator);
  return {dvec3(0.0), (wo.z > 0.0 ? p.tint : dvec3(1.0)) * f};
}

dvec3 ggxDielectricSample(const GgxDielectricParams& p, const dvec3& wo, const dvec3& u) {
  const bool outside = wo.z > 0.0;
  const dvec3 mUp = sampleGgxVisibleNormal(dvec3(wo.x, wo.y, std::abs(wo.z)), p.alpha_x, p.alpha_y, dvec2(u.y, u.z));
  const dvec3 m = outside ? mUp : dvec3(mUp.x, mUp.y, -mUp.z);  // facing wo
  const double cosO = glm::dot(wo, m);
  // A direction on the wrong side of the surface for its lobe (a microfacet seen at grazing) fails: zero.
  if (u.x < reflectProbability(p.eta, m, wo)) {
    const dvec3 wi = 2.0 * cosO * m - wo;
    return wi.z * wo.z > 0.0 ? wi : dvec3(0.0);
  }
  const double ratio = outside ? 1.0 / p.eta : p.eta;  // eta_o / eta_t
  const double sin2T = ratio * ratio * (1.0 - cosO * cosO);
  if (sin2T >= 1.0) return dvec3(0.0);  // cannot be reached: reflection had probability 1
  const dvec3 wi = -ratio * wo + (ratio * cosO - std::sqrt(1.0 - sin2T)) * m;
  return wi.z * wo.z < 0.0 ? wi : dvec3(0.0);
}

dvec3 ggxDielectricTransmissionEtas(const GgxDielectricParams& p) { return dvec3(p.eta); }

double ggxDielectricPdf(const GgxDielectricParams& p, const dvec3& wi, const dvec3& wo) {
  if (!(wi.z != 0.0 && wo.z != 0.0)) return 0.0;
  const dvec3 woUp(wo.x, wo.y, std::abs(wo.z));
  const double visibleG1 = G1_GGX(woUp, p.alpha_x, p.alpha_y);
  if (wi.z * wo.z > 0.0) {
    const dvec3 H = (wo.z > 0.0 ? 1.0 : -1.0) * glm::normalize(wi + wo);
    // D_wo(H) / (4 |wo.H|) = G1(wo) D(H) / (4 |cos_o|).
    return reflectProbability(p.eta, H, wo) * visibleG1 * D_GGX(H, p.alpha_x, p.alpha_y) / (4.0 * woUp.z);
  }
  const dvec3 H = transmissionHalfVector(p.eta, wi, wo);
  const double wiH = glm::dot(wi, H), woH = glm::dot(wo, H);
  if (!(wiH * wi.z > 0.0 && woH * wo.z > 0.0)) return 0.0;
  const double etaI = sideIndex(wi, p.eta), etaO = sideIndex(wo, p.eta);
  const double denominator = etaI * wiH + etaO * woH;
  const double visible = visibleG1 * std::abs(woH) * D_GGX(H, p.alpha_x, p.alpha_y) / woUp.z;
  return (1.0 - reflectProbability(p.eta, H, wo)) * visible * etaI * etaI * std::abs(wiH) / (denominator * denominator);
}

SpecularLobe ggxDielectricSpecularLobe(const GgxDielectricParams& p) {
  return {1.0, dvec2(p.alpha_x, p.alpha_y), false};
}

}  // namespace raylab::reference
