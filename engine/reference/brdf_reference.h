// The double-precision CPU reference of raylab's BRDF library, written from the formulas of
// docs/brdf_contract.md for clarity (never by including the GLSL: identical source could not catch a
// wrong formula). Names follow the contract and the GLSL: wi towards the light, wo towards the viewer, both
// in the local shading frame (z = shading normal), f excluding the cosine. The per-model functions and the
// shared terms (D_Beckmann, F_Schlick, ...) are in models.h and terms.h; albedo.h integrates f cos_i.
//
// Directions are used as given, never renormalised (the contract requires unit vectors): the reference then
// computes the contract's formulas on exactly the numbers the GPU received, so that a parity difference is
// the GPU's own rounding and not a difference of inputs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "shared/scene_records.h"

namespace raylab::reference {

using glm::dvec2;
using glm::dvec3;

// A material in double precision: the exact values of a gpu::MaterialRecord. Each model reads its parameters
// through the struct the registry generates for it (generated/reference_params.h: <prefix>Params).
struct Material {
  std::uint32_t model = 0;
  double delta = 0.0;
  std::array<double, gpu::kMaxMaterialParams> params{};
};
inline dvec3 paramRgb(const Material& material, std::size_t slot) {
  return {material.params[slot], material.params[slot + 1], material.params[slot + 2]};
}

Material fromRecord(const gpu::MaterialRecord& record);

// The local shading frame of the contract: n normalised, t made orthogonal to n (Gram-Schmidt) and
// normalised, b = n x t. When |t - (t.n) n|^2 <= 1e-12 (t zero or parallel to n), t is replaced by the tangent
// of Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017) built from n, exactly as
// shaders/common/frame.glsl does. Throws Error when n is zero or not finite.
struct Frame {
  dvec3 t, b, n;
};
Frame makeFrame(dvec3 n, dvec3 t);
dvec3 toLocal(const Frame& frame, const dvec3& w);

// f(wi, wo) of any model that is not a delta BSDF, in the local frame, RGB. Exactly 0 when wi.z <= 0 or wo.z <= 0 (and when
// a component is NaN or infinite); 0 for glass. Guards beyond the contract's: the specular term is 0 when
// V.H = (wo.h)/|h| <= 0, which cannot happen for unit wi, wo above the horizon (wo.h = 1 + wi.wo > 0) but can
// through the rounding of non-unit inputs at the grazing mirror configuration; h itself is never zero there
// (h_z = wi.z + wo.z > 0). For ashikhmin_shirley k = nu when h_x = h_y = 0.
dvec3 eval(const Material& material, const dvec3& wi, const dvec3& wo);

// Importance sampling (the strategy of the shared brief, written out in docs/brdfs.md, so that the GLSL and this
// reference agree): u.x < specularProbability picks the specular lobe, else the cosine-weighted diffuse lobe;
// u.y and u.z place the direction. pdf is per unit solid angle of the whole mixture. A sample whose direction
// lands at or below the horizon fails: pdf 0, wi and f zero. Otherwise f = eval(wi, wo), pdf = pdf(wi, wo).
// The free choices, fixed here: phong's frame around R is makeFrame(R, 0) (t from Duff et al.), and
// blinnphong's cos(theta_h) = u.y^(1/(s+1)) like phong's cos(alpha).
struct Sample {
  dvec3 wi{0.0};
  dvec3 f{0.0};  // eval(material, wi, wo)
  double pdf = 0.0;
};
Sample sample(const Material& material, const dvec3& wo, const dvec3& u);
double pdf(const Material& material, const dvec3& wi, const dvec3& wo);
// Probability that sample() picks the specular lobe (the model's SpecularLobe; 0 without a glossy lobe).
double specularProbability(const Material& material);

// A smooth dielectric interface (the physics of the delta BSDF glass). eta = n_inside / n_outside, n the outward normal; wi in the same space as
// n (not necessarily local). See docs/brdf_contract.md for which side is which. eta = 1 is no interface at all:
// F_exact = 0, no TIR and refracted = -wi, even at cos_i = 0 where Snell's sin^2 reaches 1.
struct DielectricEvent {
  double fresnelExact = 0.0;        // F_exact
  double fresnelSchlick = 0.0;      // F_schlick: cosine on the optically thinner side, 1 under TIR
  double fresnelSchlickNaive = 0.0; // F_schlick_naive: always cos_i
  bool tir = false;
  dvec3 reflected{0.0};
  dvec3 refracted{0.0};  // zero under total internal reflection
  dvec3 transmittance{1.0};  // the model's colour on the refracted branch as it enters
};
DielectricEvent dielectricEvent(double eta, const dvec3& wi, const dvec3& n);

}  // namespace raylab::reference
