// Sampling building blocks shared by the models: the cosine-weighted diffuse lobe, reflection about a half
// vector and directions from spherical coordinates.
#pragma once

#include <glm/glm.hpp>

namespace raylab::reference {

using glm::dvec2;
using glm::dvec3;

// Shirley & Chiu, "A Low Distortion Map Between Disk and Square", JGT 2(3), 1997: u in [0,1)^2 to the unit
// disk, area-preserving.
dvec2 sampleConcentricDisk(const dvec2& u);

// Malley's method: a concentric-disk point lifted to the hemisphere, density wi.z / pi. The lifted point can
// land exactly on the horizon (z = 0) when the disk point is on the unit circle; the caller treats it as failed.
dvec3 sampleCosineHemisphere(const dvec2& u);
double pdfCosineHemisphere(const dvec3& wi);

// wo reflected about the unit vector H: 2 (wo.H) H - wo.
dvec3 reflectAbout(const dvec3& wo, const dvec3& H);

// The unit vector at polar angle theta and azimuth phi around z, from their sines and cosines.
dvec3 sphericalDirection(double sinTheta, double cosTheta, double cosPhi, double sinPhi);

// cos(theta) = v^(1/(e+1)) for v in [0,1], the inversion of a (cos theta)^e lobe, returned with
// sin^2(theta) computed as (1 - cos)(1 + cos) with 1 - cos = -expm1(log(v)/(e+1)), which keeps its relative
// accuracy when theta is tiny (e = 1e4). v = 0 gives cos = 0.
struct PowerCosine {
  double cosTheta;
  double sinTheta;
};
PowerCosine samplePowerCosine(double v, double exponent);

}  // namespace raylab::reference
