// Directional albedo a(wo) = integral over the hemisphere of f(wi, wo) cos_i dwi, by adaptive cubature in
// coordinates that follow each lobe, so that it stays accurate for the sharpest lobes of the contract
// (s = 1e4, m = 0.001, alpha = 0.001) and at grazing wo. docs/brdfs.md gives the measured figures.
//
// The diffuse term is integrated over (cos theta_i, phi_i). The specular term is integrated in gnomonic
// (slope) coordinates around the lobe's centre, stretched by the lobe's widths so that the lobe becomes a
// round bump of unit size, in polar form (radius, angle); the radius runs up to where wi meets the horizon
// along each angle, so that the horizon is an edge of the domain instead of a cut through it:
//   - a lobe around the mirror direction of wo (SpecularLobe::aroundMirror): in wi space;
//   - any other lobe: around n in half-vector space, wi = reflect(wo, H), dwi = 4 (wo.H) dH.
// A two-sided model (rough glass) adds its transmission, integrated over its refraction half vector in the same
// coordinates and weighted by eta^2 (generalised reciprocity): for it, the albedo is the fraction of the light
// arriving from wo that is reflected or transmitted, at most 1 (docs/brdfs.md, "ggx_dielectric").
// A tabulated model (measured) is a step function, which adaptive cubature cannot converge on: its albedo is a
// Monte Carlo estimate with its own sampler (2^20 samples, fixed seed), errorEstimate three standard errors.
#pragma once

#include "reference/brdf_reference.h"

namespace raylab::reference {

struct AlbedoOptions {
  double relTolerance = 1e-9;
  int maxRegions = 20000;
};

struct Albedo {
  dvec3 value{0.0};           // diffuse + specular + transmission
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};        // reflected by the glossy lobe
  dvec3 transmission{0.0};    // a two-sided model's: transmitted, as a fraction of the light arriving from wo
  double errorEstimate = 0.0; // absolute, largest channel (the cubature's estimate; pessimistic)
  long long evaluations = 0;  // calls of the model
  bool converged = false;
};

Albedo directionalAlbedo(const Material& material, const dvec3& wo, const AlbedoOptions& options = {});

// The local direction at polar angle theta from n and azimuth phi from t.
dvec3 directionFromAngles(double theta, double phi);

}  // namespace raylab::reference
