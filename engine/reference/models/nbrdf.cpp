// Neural BRDFs in the reference: the network evaluated in double precision (engine/measured/nbrdf.h), and the
// tabulated sampler the library built from it at load. The parameter `file` is the id of the loaded file
// (measured_library.h).
#include "generated/reference_params.h"
#include "reference/models/file_sampler.h"

namespace raylab::reference {

namespace {

std::shared_ptr<const MeasuredFile> fileOf(const NbrdfParams& p) {
  std::shared_ptr<const MeasuredFile> file = measuredFile(std::uint32_t(p.file));
  checkFileKind(*file, "network", "nbrdf");
  return file;
}

}  // namespace

Lobes nbrdfEval(const NbrdfParams& p, const dvec3& wi, const dvec3& wo) {
  if (!aboveHorizon(wi, wo)) return {};
  return {dvec3(0.0), raylab::nbrdfEval(*fileOf(p)->network, wi, wo)};
}

dvec3 nbrdfSampleSpecular(const NbrdfParams& p, const dvec3& wo, const dvec2& u) {
  return fileSampleSpecular(fileOf(p)->sampling, wo, u);
}

double nbrdfPdfSpecular(const NbrdfParams& p, const dvec3& wi, const dvec3& wo) {
  return filePdfSpecular(fileOf(p)->sampling, wi, wo);
}

SpecularLobe nbrdfSpecularLobe(const NbrdfParams& p) { return fileSpecularLobe(fileOf(p)->sampling); }

}  // namespace raylab::reference
