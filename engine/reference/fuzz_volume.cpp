// The fibre volume's random walk and the maximum-likelihood fit of a linearly transformed cosine to it
// (reference/fuzz_volume.h). Written from the SGGX paper's definitions for the one distribution the fuzz uses,
// S = diag(1, 1, s^2), whose square root is diag(1, 1, s).
#include "reference/fuzz_volume.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/sampling.h"

namespace raylab::reference {
namespace {

// sigma(w) = sqrt(w^T S w): the flakes' projected area along w, per unit density, hence the extinction along w.
double projectedArea(const dvec3& w, double s) { return std::sqrt(w.x * w.x + w.y * w.y + s * s * w.z * w.z); }

// A flake normal seen from w (unit), with density proportional to max(0, w.m) D(m). SGGX's D is the normal
// distribution of the ellipsoid x^T S x = 1, the image of the unit sphere under S^(-1/2): rays along w there are rays
// along S^(1/2) w at the sphere, whose visible points are uniform on its projected disk, and the normal at the
// image of a sphere point u is along S^(1/2) u.
dvec3 sampleVisibleFlake(const dvec3& w, double s, const dvec2& u) {
  const dvec3 along = glm::normalize(dvec3(w.x, w.y, s * w.z));
  const Frame frame = makeFrame(along, dvec3(1.0, 0.0, 0.0));
  const dvec2 disk = sampleConcentricDisk(u);
  const dvec3 onSphere = disk.x * frame.t + disk.y * frame.b + std::sqrt(std::max(0.0, 1.0 - glm::dot(disk, disk))) * along;
  return glm::normalize(dvec3(onSphere.x, onSphere.y, s * onSphere.z));
}

// Light crossing the slab goes a few events deep at most (its optical thickness is at most 1 along the normal);
// this bound only stops a walk trapped by rounding.
constexpr int kMaxEvents = 100000;

}  // namespace

std::optional<dvec3> walkFuzzVolume(const dvec3& wo, double roughness, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double s = roughness * roughness;
  dvec3 direction = -wo;  // of travel
  double depth = 0.0;     // below the top, in units of the slab's thickness
  for (int event = 0; event < kMaxEvents; ++event) {
    const double sigmaT = projectedArea(direction, s);
    if (!(sigmaT > 0.0)) return direction.z > 0.0 ? std::optional<dvec3>(direction) : std::nullopt;
    depth -= direction.z * (-std::log1p(-uniform(random)) / sigmaT);
    if (depth < 0.0) return direction;
    if (depth > 1.0) return std::nullopt;
    // A specular flake reflects the direction the light came from about its normal.
    const dvec3 from = -direction;
    direction = reflectAbout(from, sampleVisibleFlake(from, s, dvec2(uniform(random), uniform(random))));
  }
  return std::nullopt;
}

namespace {

// The mean negative log-likelihood of the LTC lobe D(w) = w.z a^2 / (pi |M^-1 w|^4) over the directions, up to the
// constant mean of -log(w.z / pi), at (log a, b).
double negativeLogLikelihood(const std::vector<dvec3>& directions, double logA, double b) {
  const double a = std::exp(logA);
  double sum = 0.0;
  for (const dvec3& w : directions) {
    const dvec3 q(a * w.x + b * w.z, a * w.y, w.z);
    sum += 2.0 * std::log(glm::dot(q, q));
  }
  return sum / double(directions.size()) - 2.0 * logA;
}

// Nelder and Mead's simplex on two variables: the likelihood is smooth with one minimum, and 2-D needs nothing
// more.
dvec2 minimise(const std::vector<dvec3>& directions, dvec2 start) {
  const auto f = [&](const dvec2& x) { return negativeLogLikelihood(directions, x.x, x.y); };
  dvec2 points[3] = {start, start + dvec2(0.2, 0.0), start + dvec2(0.0, 0.2)};
  double values[3] = {f(points[0]), f(points[1]), f(points[2])};
  for (int iteration = 0; iteration < 400; ++iteration) {
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int l, int r) { return values[l] < values[r]; });
    const int best = order[0], middle = order[1], worst = order[2];
    if (glm::length(points[worst] - points[best]) < 1e-7) break;
    const dvec2 centre = 0.5 * (points[best] + points[middle]);
    const dvec2 reflected = centre + (centre - points[worst]);
    const double fReflected = f(reflected);
    if (fReflected < values[best]) {
      const dvec2 expanded = centre + 2.0 * (centre - points[worst]);
      const double fExpanded = f(expanded);
      points[worst] = fExpanded < fReflected ? expanded : reflected;
      values[worst] = std::min(fExpanded, fReflected);
    } else if (fReflected < values[middle]) {
      points[worst] = reflected;
      values[worst] = fReflected;
    } else {
      const dvec2 contracted = centre + 0.5 * (points[worst] - centre);
      const double fContracted = f(contracted);
      if (fContracted < values[worst]) {
        points[worst] = contracted;
        values[worst] = fContracted;
      } else {
        for (const int i : {middle, worst}) {
          points[i] = points[best] + 0.5 * (points[i] - points[best]);
          values[i] = f(points[i]);
        }
      }
    }
  }
  return values[0] <= values[1] && values[0] <= values[2] ? points[0] : values[1] <= values[2] ? points[1] : points[2];
}

}  // namespace

FuzzLtcFit fitFuzzLtc(double mu, double roughness, std::int64_t walks, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const double c = std::clamp(mu, 0.0, 1.0);
  const dvec3 wo(std::sqrt(1.0 - c * c), 0.0, c);
  std::vector<dvec3> directions;
  FuzzLtcFit fit;
  fit.walks = walks;
  for (std::int64_t n = 0; n < walks; ++n) {
    if (const std::optional<dvec3> out = walkFuzzVolume(wo, roughness, random); out && out->z > 0.0) {
      directions.push_back(*out);
    }
  }
  fit.reflected = std::int64_t(directions.size());
  fit.albedo = double(fit.reflected) / double(walks);
  // Below a few dozen directions the lobe is noise; its albedo is then so small that its shape does not matter.
  if (directions.size() < 32) return fit;
  const dvec2 best = minimise(directions, dvec2(0.0, 0.0));
  fit.a = std::exp(best.x);
  fit.b = best.y;
  return fit;
}

}  // namespace raylab::reference
