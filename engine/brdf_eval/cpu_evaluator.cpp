#include "brdf_eval/cpu_evaluator.h"

#include "reference/brdf_reference.h"
#include "reference/models.h"

namespace raylab {

BrdfResult evaluateBrdfCaseOnCpu(const gpu::BrdfEvalCase& input) {
  using glm::dvec3;
  const reference::Material material = reference::fromRecord(input.material);
  const dvec3 wi = glm::normalize(dvec3(input.wi));
  const dvec3 n = glm::normalize(dvec3(input.n));
  BrdfResult result;
  if (const std::optional<reference::DielectricEvent> event = reference::deltaEvent(material, wi, n)) {
    result.fresnelExact = event->fresnelExact;
    result.fresnelSchlick = event->fresnelSchlick;
    result.fresnelSchlickNaive = event->fresnelSchlickNaive;
    result.tir = event->tir;
    result.reflected = event->reflected;
    result.refracted = event->refracted;
    return result;
  }
  const reference::Frame frame = reference::makeFrame(n, dvec3(input.t));
  const dvec3 wo = glm::normalize(dvec3(input.wo));
  const dvec3 wiLocal = reference::toLocal(frame, wi), woLocal = reference::toLocal(frame, wo);
  result.f = reference::eval(material, wiLocal, woLocal);
  result.pdf = reference::pdf(material, wiLocal, woLocal);
  return result;
}

}  // namespace raylab
