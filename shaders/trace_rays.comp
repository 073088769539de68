#version 460
// Traces a list of rays against the scene with the renderer's own traversal (traceClosest, traceVisibility,
// intersectSphere, surface reconstruction) and writes each result. Used by tests (hit distances against analytic
// values) and by `raylab bench rays` (throughput and the Embree cross-check).
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"
#include "kernel/scene_bindings.glsl"
#include "kernel/surface.glsl"
#include "kernel/trace.glsl"

layout(local_size_x = 64) in;

layout(push_constant, scalar) uniform Push { ProbeParams params; };
layout(set = 0, binding = kBindingProbeRays, scalar) readonly buffer Rays { ProbeRay rays[]; };
layout(set = 0, binding = kBindingProbeHits, scalar) writeonly buffer Hits { ProbeHit hits[]; };

ProbeHit missed(ProbeRay ray) {
  ProbeHit result;
  result.t = ray.tMax;
  result.instance = kProbeMiss;
  result.primitive = kProbeMiss;
  result.frontFace = 0u;
  result.position = vec3(0.0);
  result.reserved = 0u;
  result.geometricNormal = vec3(0.0);
  result.reserved2 = 0u;
  return result;
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= params.rayCount) return;
  const ProbeRay ray = rays[i];
  ProbeHit result = missed(ray);
  if (params.mode == kProbeOcclusion) {
    if (!traceVisibility(ray.origin, ray.direction, ray.tMax)) result.instance = 0u;
    hits[i] = result;
    return;
  }
  Hit hit;
  if (traceClosest(ray.origin, ray.direction, ray.tMin, ray.tMax, hit)) {
    result.t = hit.t;
    result.instance = hit.instance;
    result.primitive = hit.primitive;
    if (params.mode == kProbeClosest) {
      const Surface s = surfaceAt(hit);
      result.frontFace = s.frontFace ? 1u : 0u;
      result.position = s.position;
      result.geometricNormal = s.geometricNormal;
    }
  }
  hits[i] = result;
}
