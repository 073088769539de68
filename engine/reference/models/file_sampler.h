// The sampler of the models whose parameter is a file (measured, nbrdf) in the reference: the half-vector table
// the library built when it loaded the file (engine/measured/measured_sampling.h), reflected about.
#pragma once

#include <algorithm>
#include <cmath>

#include "measured/measured_library.h"
#include "reference/models.h"
#include "reference/sampling.h"

namespace raylab::reference {

inline dvec3 fileSampleSpecular(const MeasuredSampling& sampling, const dvec3& wo, const dvec2& u) {
  return reflectAbout(wo, sampleMeasuredHalfVector(sampling, u));
}

inline double filePdfSpecular(const MeasuredSampling& sampling, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = glm::normalize(wi + wo);
  const double VoH = glm::dot(wo, h);
  if (!(VoH > 0.0)) return 0.0;
  return measuredHalfVectorPdf(sampling, h) / (4.0 * VoH);
}

// A lobe in H space about the normal, as wide as the theta_h that holds half the sampler's mass.
inline SpecularLobe fileSpecularLobe(const MeasuredSampling& sampling) {
  int median = 0;
  while (median + 1 < kMerlThetaH && sampling.cdf[median] < 0.5) ++median;
  const double width = std::max(0.01, std::tan(merlThetaHEdge(median + 1)));
  return {1.0 - sampling.cosineProbability, dvec2(width), false};
}

}  // namespace raylab::reference
