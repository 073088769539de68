#include "render/render_choices.h"

#include "shared/features.h"
#include "util/render_options.h"

namespace raylab {

// The enums follow the order of the options' values.
static_assert(kIntegratorValues[std::size_t(IntegratorChoice::kSlides)] == "slides" &&
              kIntegratorValues[std::size_t(IntegratorChoice::kPath)] == "path");
static_assert(kSamplingValues[gpu::kSamplingBsdf] == "bsdf" && kSamplingValues[gpu::kSamplingLight] == "light");
static_assert(kScheduleValues[std::size_t(Schedule::kWavefront)] == "wavefront");
static_assert(kBackendValues[std::size_t(BackendChoice::kPipeline)] == "pipeline");
static_assert(kFresnelValues[1] == "schlick");

IntegratorChoice parseIntegratorChoice(std::string_view value, const std::string& where) {
  return IntegratorChoice(choiceIndex(kIntegratorOption, value, where));
}

std::uint32_t parseSampling(std::string_view value, const std::string& where) {
  return std::uint32_t(choiceIndex(kSamplingOption, value, where));
}

bool parseSchlickFresnel(std::string_view value, const std::string& where) {
  return choiceIndex(kFresnelOption, value, where) == 1;
}

Schedule parseSchedule(std::string_view value, const std::string& where) {
  return Schedule(choiceIndex(kScheduleOption, value, where));
}

BackendChoice parseBackendChoice(std::string_view value, const std::string& where) {
  return BackendChoice(choiceIndex(kBackendOption, value, where));
}

Guiding parseGuiding(std::string_view value, const std::string& where) {
  return Guiding(choiceIndex(kGuidingOption, value, where));
}

}  // namespace raylab
