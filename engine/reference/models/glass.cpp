// Glass: a smooth dielectric interface, a delta BSDF (docs/brdf_contract.md, "Glass"). Its physics is the
// interface's (dielectric.cpp); the model adds its tint on the refracted branch.
#include "generated/reference_params.h"

namespace raylab::reference {

DielectricEvent glassDeltaEvent(const GlassParams& p, const dvec3& wi, const dvec3& n) {
  DielectricEvent event = dielectricEvent(p.eta, wi, n);
  event.transmittance = p.tint;
  return event;
}

}  // namespace raylab::reference
