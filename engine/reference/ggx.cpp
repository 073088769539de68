#include "reference/ggx.h"

#include <algorithm>
#include <cmath>

#include "reference/terms.h"

namespace raylab::reference {

double D_GGX(const dvec3& h, double ax, double ay) {
  if (!(h.z > 0.0)) return 0.0;
  const double b = (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z) / glm::dot(h, h);
  return 1.0 / (kPi * ax * ay * b * b);
}

double Lambda_GGX(const dvec3& w, double ax, double ay) {
  const double x = (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z);
  return 0.5 * (std::sqrt(1.0 + x) - 1.0);
}

double G1_GGX(const dvec3& w, double ax, double ay) { return 1.0 / (1.0 + Lambda_GGX(w, ax, ay)); }

double G2_GGX(const dvec3& wi, const dvec3& wo, double ax, double ay) {
  return 1.0 / (1.0 + Lambda_GGX(wi, ax, ay) + Lambda_GGX(wo, ax, ay));
}

dvec3 sampleGgxVisibleNormal(const dvec3& wo, double ax, double ay, const dvec2& u) {
  const dvec3 v = glm::normalize(dvec3(ax * wo.x, ay * wo.y, wo.z));
  const double lensq = v.x * v.x + v.y * v.y;
  const dvec3 t1 = lensq > 0.0 ? dvec3(-v.y, v.x, 0.0) / std::sqrt(lensq) : dvec3(1.0, 0.0, 0.0);
  const dvec3 t2 = glm::cross(v, t1);
  // A uniform point of the unit disk, its half beyond v's horizon squashed onto the visible part.
  const double r = std::sqrt(u.x);
  const double phi = 2.0 * kPi * u.y;
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1.0 + v.z);
  const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
  const dvec3 n = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
  return glm::normalize(dvec3(ax * n.x, ay * n.y, std::max(n.z, 0.0)));
}

double ggxReflectionPdf(const dvec3& h, const dvec3& wo, double ax, double ay) {
  return G1_GGX(wo, ax, ay) * D_GGX(h, ax, ay) / (4.0 * wo.z);
}

}  // namespace raylab::reference
