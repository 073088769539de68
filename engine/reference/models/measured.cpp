// Measured (MERL) BRDFs in the reference: the file's table in double precision, looked up as the database's
// reader does (engine/measured/merl.h), and the sampler of engine/measured/measured_sampling.h. The parameter
// `file` is the id of the loaded file (measured_library.h).
#include "generated/reference_params.h"
#include "measured/measured_library.h"
#include "reference/sampling.h"

namespace raylab::reference {

namespace {

std::shared_ptr<const MeasuredFile> fileOf(const MeasuredParams& p) { return measuredFile(std::uint32_t(p.file)); }

}  // namespace

Lobes measuredEval(const MeasuredParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {dvec3(0.0), merlLookup(fileOf(p)->table, wi, wo)};
}

dvec3 measuredSampleSpecular(const MeasuredParams& p, const dvec3& wo, const dvec2& u) {
  return reflectAbout(wo, sampleMeasuredHalfVector(fileOf(p)->sampling, u));
}

double measuredPdfSpecular(const MeasuredParams& p, const dvec3& wi, const dvec3& wo) {
  const dvec3 h = glm::normalize(wi + wo);
  const double VoH = glm::dot(wo, h);
  if (!(VoH > 0.0)) return 0.0;
  return measuredHalfVectorPdf(fileOf(p)->sampling, h) / (4.0 * VoH);
}

// A lobe in H space about the normal, as wide as the theta_h that holds half the sampler's mass.
SpecularLobe measuredSpecularLobe(const MeasuredParams& p) {
  const MeasuredSampling& sampling = fileOf(p)->sampling;
  int median = 0;
  while (median + 1 < kMerlThetaH && sampling.cdf[median] < 0.5) ++median;
  const double width = std::max(0.01, std::tan(merlThetaHEdge(median + 1)));
  return {1.0 - sampling.cosineProbability, dvec2(width), false};
}

}  // namespace raylab::reference
