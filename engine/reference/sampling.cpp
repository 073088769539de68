#include "reference/sampling.h"

#include <algorithm>
#include <cmath>

#include "reference/terms.h"

namespace raylab::reference {

dvec2 sampleConcentricDisk(const dvec2& u) {
  const double a = 2.0 * u.x - 1.0;
  const double b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return dvec2(0.0);  // the centre; the ratios below would be 0/0
  double r;
  double phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0) * (b / a);
  } else {
    r = b;
    phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
  }
  return r * dvec2(std::cos(phi), std::sin(phi));
}

dvec3 sampleCosineHemisphere(const dvec2& u) {
  const dvec2 d = sampleConcentricDisk(u);
  // Rounding can put |d| a hair above 1; the max keeps the sqrt real (the point is then on the horizon).
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}

double pdfCosineHemisphere(const dvec3& wi) { return std::max(0.0, wi.z) * kInvPi; }

dvec3 reflectAbout(const dvec3& wo, const dvec3& H) { return 2.0 * glm::dot(wo, H) * H - wo; }

dvec3 sphericalDirection(double sinTheta, double cosTheta, double cosPhi, double sinPhi) {
  return {sinTheta * cosPhi, sinTheta * sinPhi, cosTheta};
}

PowerCosine samplePowerCosine(double v, double exponent) {
  // log(0) = -inf gives cos = exp(-inf) = 0 and 1 - cos = -expm1(-inf) = 1: no special case needed.
  const double logCos = std::log(v) / (exponent + 1.0);
  const double cosTheta = std::exp(logCos);
  const double oneMinusCos = -std::expm1(logCos);
  return {cosTheta, std::sqrt(std::max(0.0, oneMinusCos * (1.0 + cosTheta)))};
}

}  // namespace raylab::reference
