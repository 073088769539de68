#version 460
// Evaluates the BRDF library on a list of cases in one dispatch (`raylab brdf eval`, the parity tests):
// f and the sampler's pdf for the BRDF models in the local shading frame, the Fresnel terms and directions for
// glass.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/bindings.h"
#include "shared/brdf_eval.h"
#include "brdf/bsdf.glsl"
#include "common/frame.glsl"

layout(local_size_x = kBrdfWorkgroupSize) in;

layout(push_constant) uniform Push { uint caseCount; };
layout(set = 0, binding = kBindingBrdfCases, scalar) readonly buffer Cases { BrdfEvalCase cases[]; };
layout(set = 0, binding = kBindingBrdfValues, scalar) writeonly buffer Values { BrdfEvalValue values[]; };

// The host rejects zero-length directions; this keeps one from turning into NaN all the same.
vec3 normalizeOrZero(vec3 v) {
  const float length2 = dot(v, v);
  return length2 > 0.0 ? v * inversesqrt(length2) : vec3(0.0);
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= caseCount) return;
  const BrdfEvalCase c = cases[i];
  const vec3 wi = normalizeOrZero(c.wi);
  const vec3 n = normalizeOrZero(c.n);

  BrdfEvalValue value;
  value.f = vec3(0.0);
  value.fresnelExact = 0.0;
  value.reflected = vec3(0.0);
  value.fresnelSchlick = 0.0;
  value.refracted = vec3(0.0);
  value.fresnelSchlickNaive = 0.0;
  value.tir = 0u;
  value.pdf = 0.0;
  if (isSpecularOnly(bsdfFlags(c.material))) {
    const DeltaEvent event = modelDeltaEvent(c.material, wi, n);
    value.fresnelExact = event.fresnelExact;
    value.fresnelSchlick = event.fresnelSchlick;
    value.fresnelSchlickNaive = event.fresnelSchlickNaive;
    value.tir = event.tir ? 1u : 0u;
    value.reflected = event.reflected;
    value.refracted = event.refracted;
  } else {
    const ShadingFrame frame = makeShadingFrame(n, c.t);
    const vec3 wiLocal = toLocal(frame, wi), woLocal = toLocal(frame, normalizeOrZero(c.wo));
    value.f = bsdfEval(c.material, wiLocal, woLocal);
    value.pdf = bsdfPdf(c.material, wiLocal, woLocal);
  }
  values[i] = value;
}
