// What the reference's models share, and its dispatch over them. Each model is one file (models/<name>.cpp,
// or a file the registry names) defining the functions generated/reference_params.h declares for it:
// <prefix>Eval, and for a glossy lobe <prefix>SampleSpecular, <prefix>PdfSpecular and <prefix>SpecularLobe, or
// for a delta BSDF <prefix>DeltaEvent. Each model's f is a diffuse term plus a specular term; the reference
// keeps the two apart (Lobes) so that the albedo quadrature can integrate each in coordinates that suit it.
// eval() of brdf_reference.h is their sum.
//
// Every function here works in the local shading frame (z = n) on unit wi, wo; the <prefix>Eval functions
// return exactly zero unless wi.z > 0 and wo.z > 0 (and both are finite), except a two-sided model's (below),
// which is zero only when a cosine is 0 or a component not finite.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "reference/brdf_reference.h"

namespace raylab::reference {

struct Lobes {
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};
  dvec3 sum() const { return diffuse + specular; }
};

// A model's glossy lobe, for the sampler's mixture and the albedo quadrature.
struct SpecularLobe {
  double probability = 0.0;  // that sample() picks this lobe rather than the cosine-weighted diffuse one
  // Widths along the two axes of the lobe's gnomonic coordinates, in units of the slope (tan of the angle from
  // its centre), chosen so that the lobe is about exp(-radius^2) in them.
  dvec2 widths{1.0};
  bool aroundMirror = false;  // centred on the mirror direction of wo (Phong), else on the normal in H space
};

// The one-sidedness guard of the contract: both directions strictly above the horizon. NaN fails it.
bool aboveHorizon(const dvec3& wi, const dvec3& wo);
// A two-sided model's guard: w finite and off the surface (on either side). NaN fails it.
bool finiteAndOffTheSurface(const dvec3& w);

// The mixture of the shared brief (docs/brdfs.md, "Sampling"): sum(rho_s) / (sum(rho_d) + sum(rho_s)), 0.5
// when both are 0.
double mixtureProbability(const dvec3& diffuse, const dvec3& specular);

// The dispatch on material.model (generated: reference_dispatch.cpp). evalLobes is zero for a delta BSDF;
// sampleSpecular, pdfSpecular and specularLobe are zero or empty without a glossy lobe; deltaEvent is empty
// unless the model is a delta BSDF. The sampled direction may lie below the horizon, which makes the sample
// fail; the density is per unit solid angle of wi, for wi and wo above the horizon.
Lobes evalLobes(const Material& material, const dvec3& wi, const dvec3& wo);
dvec3 sampleSpecular(const Material& material, const dvec3& wo, const dvec2& u);
double pdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo);
std::optional<SpecularLobe> specularLobe(const Material& material);
std::optional<DielectricEvent> deltaEvent(const Material& material, const dvec3& wi, const dvec3& n);
std::uint32_t lobeFlags(const Material& material);
// A two-sided model (transmission with a density: rough glass) takes wi and wo on either side of the normal and
// samples both hemispheres itself, u.x choosing the lobe: its direction (zero when the sample fails) and density.
// Empty for every other model.
std::optional<dvec3> sampleTwoSided(const Material& material, const dvec3& wo, const dvec3& u);
std::optional<double> pdfTwoSided(const Material& material, const dvec3& wi, const dvec3& wo);
// The absorption coefficient per unit length inside a transmissive material (a model's `medium:` line: openpbr's
// volume); zero for every other model and material.
dvec3 mediumAbsorption(const Material& material);
// A two-sided model's index of refraction, inside over outside, per channel (they differ where it disperses; 1
// through a thin wall); empty for the others.
std::optional<dvec3> transmissionEtas(const Material& material);
// A model whose f is a table read from a file (measured): a step function of the directions, which the albedo
// integrates by sampling rather than by adaptive cubature.
bool isTabulated(const Material& material);
// A material whose transmission the albedo quadrature's refraction coordinates do not fit (a model's `albedo
// sampled when:` line: openpbr's thin walls, whose light goes straight through): its albedo is a Monte Carlo
// estimate with its own sampler.
bool albedoBySampling(const Material& material);

}  // namespace raylab::reference
