#version 460
// Traces a list of rays against the scene with the renderer's own traversal (traceClosest, traceVisibility,
// intersectSphere, surface reconstruction) and writes each result: the ray-query backend's probe. Used by
// tests (hit distances against analytic values) and by `raylab bench rays` (throughput, the Embree
// cross-check). trace_rays.rgen is the same probe through the ray-tracing pipeline.
#extension GL_EXT_ray_query : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"
#include "kernel/scene_bindings.glsl"

layout(local_size_x = kProbeWorkgroupSize) in;

layout(push_constant, scalar) uniform Push { ProbeParams params; };
layout(set = 0, binding = kBindingProbeRays, scalar) readonly buffer Rays { ProbeRay rays[]; };
layout(set = 0, binding = kBindingProbeHits, scalar) writeonly buffer Hits { ProbeHit hits[]; };

#include "kernel/trace_query.glsl"
#include "kernel/probe.glsl"

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < params.rayCount) probeRay(i);
}
