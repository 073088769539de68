// Measured (MERL) BRDFs in the reference: the file's table in double precision, looked up as the database's
// reader does (engine/measured/merl.h), and the sampler of engine/measured/measured_sampling.h. The parameter
// `file` is the id of the loaded file (measured_library.h).
#include "generated/reference_params.h"
#include "reference/models/file_sampler.h"

namespace raylab::reference {

namespace {

std::shared_ptr<const MeasuredFile> fileOf(const MeasuredParams& p) {
  std::shared_ptr<const MeasuredFile> file = measuredFile(std::uint32_t(p.file));
  checkFileKind(*file, "file", "measured");
  return file;
}

}  // namespace

Lobes measuredEval(const MeasuredParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {dvec3(0.0), merlLookup(fileOf(p)->table, wi, wo)};
}

dvec3 measuredSampleSpecular(const MeasuredParams& p, const dvec3& wo, const dvec2& u) {
  return fileSampleSpecular(fileOf(p)->sampling, wo, u);
}

double measuredPdfSpecular(const MeasuredParams& p, const dvec3& wi, const dvec3& wo) {
  return filePdfSpecular(fileOf(p)->sampling, wi, wo);
}

SpecularLobe measuredSpecularLobe(const MeasuredParams& p) { return fileSpecularLobe(fileOf(p)->sampling); }

}  // namespace raylab::reference
