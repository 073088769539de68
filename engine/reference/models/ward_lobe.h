// The Ward lobe the three Ward normalisations share (ward, ward_duer, ward_gmd), as shaders/brdf/ward_lobe.glsl:
// its exponent (Ward, "Measuring and Modeling Anisotropic Reflection", SIGGRAPH 1992, eq. 5b with the
// contract's h), e = ((h_x / ax)^2 + (h_y / ay)^2) / h_z^2, and the half-vector sampler of Walter, "Notes on
// the Ward BRDF", Cornell PCG-05-06, 2005, with its density.
#pragma once

#include "reference/models.h"

namespace raylab::reference {

double wardExponent(const dvec3& h, double alphaX, double alphaY);
dvec3 wardLobeSample(double alphaX, double alphaY, const dvec3& wo, const dvec2& u);
double wardLobePdf(double alphaX, double alphaY, const dvec3& wi, const dvec3& wo);
// exp(-(p/ax)^2 - (q/ay)^2) in H space.
SpecularLobe wardSpecularLobe(const dvec3& rhoD, const dvec3& rhoS, double alphaX, double alphaY);

}  // namespace raylab::reference
