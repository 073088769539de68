#version 460
// Draws bsdfSample for one material and outgoing direction, one sample per host-provided triple of uniform
// numbers, and evaluates bsdfEval and bsdfPdf again at each sampled direction (the sampling tests).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/bindings.h"
#include "shared/brdf_eval.h"
#include "brdf/bsdf.glsl"

layout(local_size_x = kBrdfWorkgroupSize) in;

layout(push_constant, scalar) uniform Push { BrdfSampleParams params; };
layout(set = 0, binding = kBindingBrdfUniforms, scalar) readonly buffer Uniforms { vec3 uniforms[]; };
layout(set = 0, binding = kBindingBrdfSamples, scalar) writeonly buffer Samples { BrdfSampleValue samples[]; };

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= params.count) return;
  const BsdfSample s = bsdfSample(params.material, params.wo, uniforms[i]);
  BrdfSampleValue value;
  value.wi = s.wi;
  value.pdf = s.pdf;
  value.f = s.f;
  value.evalPdf = s.pdf > 0.0 ? bsdfPdf(params.material, s.wi, params.wo) : 0.0;
  value.evalF = s.pdf > 0.0 ? bsdfEval(params.material, s.wi, params.wo) : vec3(0.0);
  value.reserved = 0u;
  samples[i] = value;
}
