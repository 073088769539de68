// Traversal through the ray-tracing pipeline (the pipeline backend): the shadow ray as a traceRayEXT that stops
// at its first hit, skips every closest-hit program and reports visibility through the shadow miss program.
// The pipeline's counterpart of kernel/trace_query.glsl's traceVisibility, for any stage that traces shadow
// rays (closest-hit programs, the probe's raygen). Needs kernel/scene_bindings.glsl and GL_EXT_ray_tracing.
#ifndef RAYLAB_KERNEL_TRACE_PIPELINE_GLSL
#define RAYLAB_KERNEL_TRACE_PIPELINE_GLSL

#include "common/specialization.glsl"
#include "shared/ray_tracing.h"

layout(location = kPayloadShadow) rayPayloadEXT uint shadowVisible;

// True when nothing lies on the ray in [0, tMax].
bool traceVisibility(vec3 origin, vec3 direction, float tMax) {
  shadowVisible = 0u;
  // Alpha-tested triangles run alpha.rahit (their geometry is not opaque); the others commit at once.
  const uint opaque = featureEnabled(kFeatureAlpha) ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT;
  traceRayEXT(tlas, opaque | gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT, 0xFFu, 0u, 1u,
              kMissShadow, origin, 0.0, direction, tMax, kPayloadShadow);
  return shadowVisible != 0u;
}

#endif
