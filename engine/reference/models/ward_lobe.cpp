#include "ward_lobe.h"

#include <cmath>

#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {

double wardExponent(const dvec3& h, double alphaX, double alphaY) {
  const double x = h.x / alphaX;
  const double y = h.y / alphaY;
  return (x * x + y * y) / (h.z * h.z);
}

dvec3 wardLobeSample(double ax, double ay, const dvec3& wo, const dvec2& u) {
  // phi_h = atan((ay/ax) tan(2 pi u.z)) in the quadrant of 2 pi u.z: the direction of (ax cos, ay sin).
  const double xi = 2.0 * kPi * u.y;
  const double a = ax * std::cos(xi);
  const double b = ay * std::sin(xi);
  const double r = std::hypot(a, b);  // > 0: cos and sin never vanish together
  const double cosPhi = a / r;
  const double sinPhi = b / r;
  const double tan2 = -std::log1p(-u.x) / (cosPhi * cosPhi / (ax * ax) + sinPhi * sinPhi / (ay * ay));
  const double cosTheta = 1.0 / std::sqrt(1.0 + tan2);
  const double sinTheta = std::sqrt(tan2) * cosTheta;
  return reflectAbout(wo, sphericalDirection(sinTheta, cosTheta, cosPhi, sinPhi));
}

double wardLobePdf(double ax, double ay, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = wi + wo;
  const double length = glm::length(h);
  const double VoH = glm::dot(wo, h) / length;
  if (!(VoH > 0.0)) return 0.0;  // only through rounding of non-unit inputs, see cookTorranceEval
  const double lobe = std::exp(-wardExponent(h, ax, ay));
  if (lobe == 0.0) return 0.0;  // keeps 0 * inf out of 1 / NoH^3
  const double NoH = h.z / length;
  return lobe / (4.0 * kPi * ax * ay * VoH * NoH * NoH * NoH);
}

SpecularLobe wardSpecularLobe(const dvec3& rhoD, const dvec3& rhoS, double alphaX, double alphaY) {
  return {mixtureProbability(rhoD, rhoS), {alphaX, alphaY}, false};
}

}  // namespace raylab::reference
