#include <cmath>

#include "reference/brdf_reference.h"
#include "util/error.h"

namespace raylab::reference {

namespace {

// Any unit vector orthogonal to the unit vector n, without a singularity: Duff et al., "Building an
// Orthonormal Basis, Revisited", JCGT 6(1), 2017 (the sign choice of shaders/common/frame.glsl: n.z = -0
// counts as positive).
dvec3 anyTangent(const dvec3& n) {
  const double sign = n.z >= 0.0 ? 1.0 : -1.0;
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  return {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

}  // namespace

Frame makeFrame(dvec3 n, dvec3 t) {
  const double nLength2 = glm::dot(n, n);
  if (!(nLength2 > 0.0) || !std::isfinite(nLength2)) throw Error("makeFrame: the normal is zero or not finite");
  n /= std::sqrt(nLength2);
  t -= glm::dot(t, n) * n;
  const double length2 = glm::dot(t, t);
  // Below 1e-12 the hint is numerically parallel to n (or zero) and its direction is noise.
  t = length2 > 1e-12 ? t / std::sqrt(length2) : anyTangent(n);
  return {t, glm::cross(n, t), n};
}

dvec3 toLocal(const Frame& frame, const dvec3& w) {
  return {glm::dot(w, frame.t), glm::dot(w, frame.b), glm::dot(w, frame.n)};
}

}  // namespace raylab::reference
