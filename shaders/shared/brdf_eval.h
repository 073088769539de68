// Host/device structs of the BRDF evaluation kernels: brdf_eval.comp (`raylab brdf eval`, parity tests) and
// brdf_sample.comp (sampling tests). Scalar layout, as everywhere in shared/.
#ifndef RAYLAB_SHARED_BRDF_EVAL_H
#define RAYLAB_SHARED_BRDF_EVAL_H

#include "compat.h"
#include "scene_records.h"

RL_NAMESPACE_BEGIN

// One row of a CSV: a material and its directions in world space as read (the kernel normalises wi, wo
// and n and builds the shading frame from n and the tangent hint t). Glass reads only wi and n.
RL_CONST uint kBrdfWorkgroupSize = 64;  // brdf_eval.comp and brdf_sample.comp

struct BrdfEvalCase {
  MaterialRecord material;
  vec3 wi;
  vec3 wo;
  vec3 n;
  vec3 t;  // may be zero or parallel to n: any tangent is used then
};
RL_CHECK_SIZE(BrdfEvalCase, 288);

// What brdf_eval.comp computes for one case: f for BRDF models, the glass quantities for glass.
struct BrdfEvalValue {
  vec3 f;
  float fresnelExact;
  vec3 reflected;  // world space
  float fresnelSchlick;
  vec3 refracted;  // world space; zero under total internal reflection
  float fresnelSchlickNaive;
  uint tir;        // 1 under total internal reflection
  float pdf;       // bsdfPdf(wi, wo) of the BRDF models' sampler (the Python module's brdf.pdf)
};
RL_CHECK_SIZE(BrdfEvalValue, 56);

// brdf_sample.comp push constants: one material and one outgoing direction, `count` samples.
struct BrdfSampleParams {
  MaterialRecord material;
  vec3 wo;  // local shading frame, unit length
  uint count;
};
RL_CHECK_SIZE(BrdfSampleParams, 256);

// One bsdfSample draw, with bsdfEval and bsdfPdf evaluated again at its direction for the consistency
// test. pdf 0: the sample failed.
struct BrdfSampleValue {
  vec3 wi;  // local shading frame
  float pdf;
  vec3 f;
  float evalPdf;  // bsdfPdf(wi, wo)
  vec3 evalF;     // bsdfEval(wi, wo)
  uint reserved;
};
RL_CHECK_SIZE(BrdfSampleValue, 48);

RL_NAMESPACE_END

#endif
