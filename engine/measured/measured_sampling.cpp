#include "measured/measured_sampling.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// Solid angle of theta_h bin j: the ring between its edges.
double binSolidAngle(int j) { return 2.0 * kPi * (std::cos(merlThetaHEdge(j)) - std::cos(merlThetaHEdge(j + 1))); }

double binCentre(int j) {
  const double u = (j + 0.5) / kMerlThetaH;
  return u * u * 0.5 * kPi;
}

}  // namespace

double merlThetaHEdge(int j) {
  const double u = double(j) / kMerlThetaH;
  return u * u * 0.5 * kPi;
}

int merlThetaHBin(double thetaH) {
  if (!(thetaH > 0.0)) return 0;
  return std::clamp(static_cast<int>(std::sqrt(thetaH / (0.5 * kPi)) * kMerlThetaH), 0, kMerlThetaH - 1);
}

MeasuredSampling measuredSampling(const MerlTable& table) {
  return binnedSampling(
      [&table](int h, int d, int p) {
        const std::size_t i = std::size_t(p) + std::size_t(kMerlPhiD) * (std::size_t(d) + std::size_t(kMerlThetaD) * h);
        const glm::dvec3 stored(table.stored[i], table.stored[i + kMerlSamples], table.stored[i + 2 * kMerlSamples]);
        return stored * glm::dvec3(kMerlScale[0], kMerlScale[1], kMerlScale[2]);
      },
      1);
}

MeasuredSampling binnedSampling(const std::function<glm::dvec3(int h, int d, int p)>& value, int phiStride) {
  constexpr int kNearMirrorThetaD = kMerlThetaD / 3;  // theta_d < 30 degrees
  std::array<double, kMerlThetaH> weight{};
  for (int h = 0; h < kMerlThetaH; ++h) {
    double sum = 0.0;
    int count = 0;
    for (int d = 0; d < kNearMirrorThetaD; ++d) {
      for (int p = 0; p < kMerlPhiD; p += phiStride) {
        const glm::dvec3 f = value(h, d, p);
        if (f.x < 0.0 || f.y < 0.0 || f.z < 0.0) continue;  // missing
        sum += luminance(f);
        ++count;
      }
    }
    const double c = std::cos(binCentre(h));
    weight[h] = count > 0 ? sum / count * c * c * c * binSolidAngle(h) : 0.0;
  }
  double total = 0.0;
  for (double w : weight) total += w;
  MeasuredSampling sampling;
  if (!(total > 0.0) || !std::isfinite(total)) {
    // Nothing near the mirror configuration: half vectors by cos theta_h (a cosine lobe in h).
    total = 0.0;
    for (int h = 0; h < kMerlThetaH; ++h) total += weight[h] = std::cos(binCentre(h)) * binSolidAngle(h);
  }
  // Edge densities from the bins' mean densities, then normalised so that the trapezoids over the rings sum to 1.
  std::array<double, kMerlThetaH> binDensity{};
  for (int h = 0; h < kMerlThetaH; ++h) binDensity[h] = weight[h] / total / binSolidAngle(h);
  sampling.density[0] = binDensity[0];
  sampling.density[kMerlThetaH] = binDensity[kMerlThetaH - 1];
  for (int k = 1; k < kMerlThetaH; ++k) sampling.density[k] = 0.5 * (binDensity[k - 1] + binDensity[k]);
  double mass = 0.0;
  for (int h = 0; h < kMerlThetaH; ++h) mass += binSolidAngle(h) * 0.5 * (sampling.density[h] + sampling.density[h + 1]);
  for (double& d : sampling.density) d /= mass;
  double running = 0.0;
  for (int h = 0; h < kMerlThetaH; ++h) {
    sampling.pmf[h] = binSolidAngle(h) * 0.5 * (sampling.density[h] + sampling.density[h + 1]);
    running += sampling.pmf[h];
    sampling.cdf[h] = running;
  }
  sampling.cdf[kMerlThetaH - 1] = 1.0;

  // The albedo at normal incidence (wo = n, wi = reflect(n, h): theta_i = 2 theta_h, dwi = 4 cos theta_h dh) and
  // its diffuse floor, the least f along that curve up to theta_i = 80 degrees.
  const glm::dvec3 n(0.0, 0.0, 1.0);
  double albedo = 0.0, floor = INFINITY;
  for (int h = 0; h < kMerlThetaH; ++h) {
    const double thetaH = binCentre(h);
    if (2.0 * thetaH >= 0.5 * kPi) break;
    const glm::dvec3 half(std::sin(thetaH), 0.0, std::cos(thetaH));
    const glm::dvec3 wi = 2.0 * half.z * half - n;
    const std::size_t i = merlIndex(wi, n);
    const glm::dvec3 binned = value(int(i / (kMerlThetaD * kMerlPhiD)), int(i / kMerlPhiD % kMerlThetaD), int(i % kMerlPhiD));
    const double f = luminance(glm::max(binned, glm::dvec3(0.0)));  // missing: 0, as merlLookup gives it
    albedo += f * wi.z * 4.0 * half.z * binSolidAngle(h);
    if (2.0 * thetaH < 80.0 / 180.0 * kPi) floor = std::min(floor, f);
  }
  sampling.cosineProbability = albedo > 0.0 && std::isfinite(floor) ? std::clamp(kPi * floor / albedo, 0.1, 0.9) : 0.5;
  return sampling;
}

glm::dvec3 sampleMeasuredHalfVector(const MeasuredSampling& sampling, const glm::dvec2& u) {
  const int j = std::min(int(std::upper_bound(sampling.cdf.begin(), sampling.cdf.end(), u.x) - sampling.cdf.begin()),
                         kMerlThetaH - 1);
  const double below = j > 0 ? sampling.cdf[j - 1] : 0.0;
  const double v = sampling.pmf[j] > 0.0 ? std::clamp((u.x - below) / sampling.pmf[j], 0.0, 1.0) : 0.5;
  // t along cos theta_h from edge j to edge j + 1, with density a (1 - t) + b t: the root of the quadratic cdf in
  // the form without cancellation.
  const double a = sampling.density[j], b = sampling.density[j + 1];
  const double t = a + b > 0.0 ? v * (a + b) / (a + std::sqrt(std::max(0.0, a * a + v * (b * b - a * a)))) : v;
  const double c0 = std::cos(merlThetaHEdge(j)), c1 = std::cos(merlThetaHEdge(j + 1));
  const double cosTheta = c0 + std::clamp(t, 0.0, 1.0) * (c1 - c0);
  const double sinTheta = std::sqrt(std::max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
  const double phi = 2.0 * kPi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

double measuredHalfVectorPdf(const MeasuredSampling& sampling, const glm::dvec3& h) {
  if (!(h.z > 0.0)) return 0.0;
  const double length = glm::length(h);
  const int j = merlThetaHBin(std::atan2(std::hypot(h.x, h.y), h.z));
  const double c0 = std::cos(merlThetaHEdge(j)), c1 = std::cos(merlThetaHEdge(j + 1));
  const double t = std::clamp((c0 - h.z / length) / (c0 - c1), 0.0, 1.0);
  return sampling.density[j] + t * (sampling.density[j + 1] - sampling.density[j]);
}

}  // namespace raylab
