#include "brdf_eval/cpu_evaluator.h"

#include "reference/brdf_reference.h"

namespace raylab {

BrdfResult evaluateBrdfCaseOnCpu(const gpu::BrdfEvalCase& input) {
  using glm::dvec3;
  const reference::Material material = reference::fromRecord(input.material);
  const dvec3 wi = glm::normalize(dvec3(input.wi));
  const dvec3 n = glm::normalize(dvec3(input.n));
  BrdfResult result;
  if (input.material.model == gpu::kModelGlass) {
    const reference::GlassResult glass = reference::glass(material.eta, wi, n);
    result.fresnelExact = glass.fresnelExact;
    result.fresnelSchlick = glass.fresnelSchlick;
    result.fresnelSchlickNaive = glass.fresnelSchlickNaive;
    result.tir = glass.tir;
    result.reflected = glass.reflected;
    result.refracted = glass.refracted;
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
