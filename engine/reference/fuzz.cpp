// The fuzz layer's fitted lobe (reference/fuzz.h).
#include "reference/fuzz.h"

#include <algorithm>
#include <cmath>

#include "reference/sampling.h"
#include "reference/terms.h"

namespace raylab::reference {
namespace {

// cos and sin of wo's azimuth; (1, 0) at the normal, where D is round and any frame serves.
dvec2 azimuthOf(const dvec3& wo) {
  const double length = std::hypot(wo.x, wo.y);
  return length > 0.0 ? dvec2(wo.x / length, wo.y / length) : dvec2(1.0, 0.0);
}

}  // namespace

FuzzLobe fuzzLobe(double mu, double roughness) {
  constexpr double kLast = gpu::kFuzzLtcSize - 1;
  const double x = std::clamp(mu, 0.0, 1.0) * kLast, y = std::clamp(roughness, 0.0, 1.0) * kLast;
  const int j = std::min(int(x), int(kLast) - 1), i = std::min(int(y), int(kLast) - 1);
  const double tx = x - j, ty = y - i;
  double v[3];
  for (int k = 0; k < 3; ++k) {
    const auto at = [k](int row, int column) { return double(kFuzzLtcTable[3 * (row * gpu::kFuzzLtcSize + column) + k]); };
    v[k] = (1.0 - ty) * ((1.0 - tx) * at(i, j) + tx * at(i, j + 1)) + ty * ((1.0 - tx) * at(i + 1, j) + tx * at(i + 1, j + 1));
  }
  return {v[0], v[1], v[2]};
}

double fuzzDensity(const dvec3& wi, const dvec3& wo, const FuzzLobe& lobe) {
  if (!(wi.z > 0.0)) return 0.0;
  const dvec2 phi = azimuthOf(wo);
  const double x = phi.x * wi.x + phi.y * wi.y, y = -phi.y * wi.x + phi.x * wi.y;
  const dvec3 q(lobe.a * x + lobe.b * wi.z, lobe.a * y, wi.z);
  const double q2 = glm::dot(q, q);
  return wi.z * lobe.a * lobe.a / (kPi * q2 * q2);
}

dvec3 sampleFuzz(const dvec3& wo, const FuzzLobe& lobe, const dvec2& u) {
  // A cosine-distributed direction through M = (M^-1)^-1, then back from wo's azimuthal frame.
  const dvec3 c = sampleCosineHemisphere(u);
  const dvec3 local((c.x - lobe.b * c.z) / lobe.a, c.y / lobe.a, c.z);
  const dvec2 phi = azimuthOf(wo);
  return glm::normalize(dvec3(phi.x * local.x - phi.y * local.y, phi.y * local.x + phi.x * local.y, local.z));
}

}  // namespace raylab::reference
