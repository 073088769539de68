// The Ward lobe the three Ward normalisations share (ward, ward_duer, ward_gmd), as shaders/brdf/ward_lobe.glsl:
// its exponent (Ward, "Measuring and Modeling Anisotropic Reflection", SIGGRAPH 1992, eq. 5b with the
// contract's h), e = ((h_x / ax)^2 + (h_y / ay)^2) / h_z^2, and the half-vector sampler of Walter, "Notes on
// the Ward BRDF", Cornell PCG-05-06, 2005, with its density.
#pragma once

#include <cmath>

#include "reference/models.h"
#include "reference/terms.h"

namespace raylab::reference {

double wardExponent(const dvec3& h, double alphaX, double alphaY);

// The family's f = rho_d/pi + rho_s spec, where spec(lobe, h) is the variant's specular term given
// lobe = exp(-e) and the unnormalised h = wi + wo.
template <class Spec>
Lobes wardFamilyEval(const dvec3& rhoD, const dvec3& rhoS, double alphaX, double alphaY, const dvec3& wi,
                     const dvec3& wo, Spec spec) {
  if (!aboveHorizon(wi, wo)) return {};
  const Lobes diffuseOnly{rhoD * kInvPi, dvec3(0.0)};
  const dvec3 h = wi + wo;
  const double lobe = std::exp(-wardExponent(h, alphaX, alphaY));
  // Once exp(-e) underflows the value is 0; stopping here keeps 0 * inf out of ward_gmd's 1/h_z^4.
  if (lobe == 0.0) return diffuseOnly;
  return {diffuseOnly.diffuse, rhoS * spec(lobe, h)};
}
dvec3 wardLobeSample(double alphaX, double alphaY, const dvec3& wo, const dvec2& u);
double wardLobePdf(double alphaX, double alphaY, const dvec3& wi, const dvec3& wo);
// exp(-(p/ax)^2 - (q/ay)^2) in H space.
SpecularLobe wardSpecularLobe(const dvec3& rhoD, const dvec3& rhoS, double alphaX, double alphaY);

}  // namespace raylab::reference
