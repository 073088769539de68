// The viewer's lobe plot: a material's BRDF in its plane of incidence, and its directional albedo against angle.
// Local frame: n = +z, tangent t = +x. Light arrives from the -x side at polar angle theta_i,
// wi = (-sin theta_i, 0, cos theta_i); the outgoing direction sweeps the plane, wo = (sin theta_o, 0, cos theta_o)
// for theta_o in [-90, 90] degrees, so the mirror direction is theta_o = +theta_i. The plot shows
// f_r(wi, wo) cos theta_o: the light scattered per solid angle, whose integral over wo is the albedo. A two-sided
// model (rough glass) is plotted over the whole plane: theta_o from -180 to 179 degrees, |theta_o| > 90 inside the
// surface, and f |cos theta_o|.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "shared/brdf_eval.h"

namespace raylab {

inline constexpr std::uint32_t kLobeSamples = 181;  // theta_o every degree
inline constexpr std::uint32_t kLobeSamplesTwoSided = 360;  // every degree around the plane
inline constexpr std::uint32_t kAlbedoSamples = 19;  // theta every 5 degrees, 0..90

// The cases of one lobe: kLobeSamples outgoing directions, theta_o from -90 to 90 degrees, or for a two-sided
// model kLobeSamplesTwoSided from -180 to 179.
std::vector<gpu::BrdfEvalCase> lobeCases(const gpu::MaterialRecord& material, float thetaIDegrees);
bool lobeIsTwoSided(const gpu::MaterialRecord& material);
float lobeAngleDegrees(std::uint32_t sample, bool twoSided = false);  // theta_o of case `sample`

// f_r |cos theta_o| of each case from the device's values (glass and other delta lobes have none: all zero).
std::vector<glm::vec3> lobeValues(std::span<const gpu::BrdfEvalCase> cases, std::span<const gpu::BrdfEvalValue> values);

// Directional albedo at theta = 0, 5, ..., 90 degrees, by the reference's adaptive cubature (double precision, a
// relative tolerance of 1e-4: a few milliseconds a material).
struct AlbedoCurve {
  std::vector<float> thetaDegrees;
  std::vector<glm::vec3> albedo;
};
AlbedoCurve albedoCurve(const gpu::MaterialRecord& material);

// The lobe as CSV, for scripts (`save lobe`) and the tests: theta_i,theta_o,wi,wo,f (r g b),fcos (r g b), then
// the albedo rows as albedo,theta,value (r g b). Directions with 9 significant digits: exactly the float32
// values evaluated, so `raylab brdf eval` on them gives the same f.
std::string formatLobeCsv(const gpu::MaterialRecord& material, float thetaIDegrees,
                          std::span<const gpu::BrdfEvalCase> cases, std::span<const gpu::BrdfEvalValue> values,
                          const AlbedoCurve& albedo);

}  // namespace raylab
