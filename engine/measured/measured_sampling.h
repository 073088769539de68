// Importance sampling of a measured (MERL) BRDF, shared by the reference and the kernels (docs/brdfs.md,
// "measured"): a half vector drawn from a table over the database's own theta_h bins and reflected about, mixed
// with cosine-weighted directions. The half vector's density per unit solid angle is uniform in phi_h and
// piecewise linear in cos theta_h between the bins' edges: continuous, so that no step of the density shows in a
// render's noise or defeats the quadrature of the chi^2 test. Bin j weighs the mean luminance of its samples with
// theta_d < 30 degrees times cos^3 theta_h (for a microfacet BRDF f cos^2 theta_h ~ D near the mirror
// configuration, and D cos theta_h is the half vector's density); an edge takes the mean of its two bins'
// densities. The cosine lobe's probability is the diffuse floor's share of the albedo at normal incidence, within
// [0.1, 0.9], so that neither strategy is ever left out.
#pragma once

#include <array>
#include <functional>

#include <glm/glm.hpp>

#include "measured/merl.h"

namespace raylab {

struct MeasuredSampling {
  std::array<double, kMerlThetaH> pmf{};          // probability of theta_h bin j, summing to 1
  std::array<double, kMerlThetaH> cdf{};          // inclusive running sum, the last exactly 1
  std::array<double, kMerlThetaH + 1> density{};  // of h per unit solid angle at edge k (theta_h = merlThetaHEdge(k))
  double cosineProbability = 0.5;                 // of the cosine-weighted lobe
};

MeasuredSampling measuredSampling(const MerlTable& table);
// The same sampler for any BRDF given at the database's bins: value(h, d, p) is f (RGB) at bin (theta_h, theta_d,
// phi_d), negative in a channel where the sample is missing. Every `phiStride`-th phi_d bin is read (a neural
// BRDF is smooth in phi_d, and each value costs a network evaluation).
MeasuredSampling binnedSampling(const std::function<glm::dvec3(int h, int d, int p)>& value, int phiStride);

// Lower edge of theta_h bin j (j = 90: pi/2): theta = (j / 90)^2 pi/2, the database's non-linear axis.
double merlThetaHEdge(int j);
// The bin of theta_h in [0, pi/2], as merlIndex takes it.
int merlThetaHBin(double thetaH);

// A half vector (upper hemisphere, unit) for u in [0, 1)^2, and its density per unit solid angle of h.
glm::dvec3 sampleMeasuredHalfVector(const MeasuredSampling& sampling, const glm::dvec2& u);
double measuredHalfVectorPdf(const MeasuredSampling& sampling, const glm::dvec3& h);

}  // namespace raylab
