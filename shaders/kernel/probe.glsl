// The ray probe (rays in, closest hits out) shared by both backends' entry points: trace_rays.comp and
// trace_rays.rgen. Needs the scene bindings, `params` (ProbeParams), `rays`, `hits`, and the backend's
// traceClosest and traceVisibility.
#ifndef RAYLAB_KERNEL_PROBE_GLSL
#define RAYLAB_KERNEL_PROBE_GLSL

#include "kernel/surface.glsl"

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

void probeRay(uint i) {
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

#endif
