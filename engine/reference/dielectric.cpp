// A smooth dielectric interface (docs/brdf_contract.md, the delta BSDF "glass"): which side the light comes
// from, mirror reflection, Snell refraction with total internal reflection, and three Fresnel factors (the
// exact unpolarised one the renderer uses and two Schlick forms for comparison).
#include <cmath>

#include "reference/brdf_reference.h"
#include "reference/terms.h"

namespace raylab::reference {

DielectricEvent dielectricEvent(double eta, const dvec3& wi, const dvec3& n) {
  DielectricEvent result;
  const double cosN = glm::dot(wi, n);
  const bool fromOutside = cosN >= 0.0;
  const double etaI = fromOutside ? 1.0 : eta;
  const double etaT = fromOutside ? eta : 1.0;
  const dvec3 nn = fromOutside ? n : -n;
  const double cosI = fromOutside ? cosN : -cosN;
  const double f0 = F0FromEta(eta);

  result.reflected = 2.0 * cosI * nn - wi;
  result.fresnelSchlickNaive = F_Schlick(f0, cosI);  // the student form: cos_i on either side, no TIR test

  if (eta == 1.0) {
    // No interface: F = 0 and the ray goes straight on. Tested before TIR because at cos_i = 0 Snell's
    // sin^2 = 1 would otherwise call the grazing ray totally reflected (docs/brdfs.md, "Glass").
    result.refracted = -wi;
    result.fresnelSchlick = F_Schlick(f0, cosI);  // Schlick's (1 - cos)^5 does not vanish at eta = 1
    return result;
  }

  const double ratio = etaI / etaT;
  const double sin2T = ratio * ratio * (1.0 - cosI * cosI);
  if (sin2T >= 1.0) {
    result.tir = true;
    result.fresnelExact = 1.0;
    result.fresnelSchlick = 1.0;
    return result;  // refracted stays zero
  }
  const double cosT = std::sqrt(1.0 - sin2T);
  result.refracted = -ratio * wi + (ratio * cosI - cosT) * nn;
  // etaI cosI + etaT cosT > 0 here: cosT > 0 because sin2T < 1.
  result.fresnelExact = F_DielectricExact(etaI, etaT, cosI, cosT);
  // Schlick's approximation holds with the angle on the optically thinner side (the outside for eta > 1).
  result.fresnelSchlick = F_Schlick(f0, etaI <= etaT ? cosI : cosT);
  return result;
}

}  // namespace raylab::reference
