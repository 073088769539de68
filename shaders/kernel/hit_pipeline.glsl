// The committed hit as a closest-hit program of the pipeline backend sees it: the same Hit that
// kernel/trace_query.glsl's traceClosest reads from a ray query, from the stage's built-ins and the hit-group
// record. For closest-hit stages only (GL_EXT_ray_tracing).
#ifndef RAYLAB_KERNEL_HIT_PIPELINE_GLSL
#define RAYLAB_KERNEL_HIT_PIPELINE_GLSL

#include "kernel/payload.glsl"
#include "shared/ray_tracing.h"

// Triangles: the barycentrics of the hit; spheres: sphere.rint reports vec2(0), as the ray-query backend has it.
hitAttributeEXT vec2 hitBarycentrics;
layout(shaderRecordEXT, scalar) buffer HitGroupRecord { HitGroupData hitGroup; };

Hit committedHit() {
  Hit hit;
  hit.t = gl_HitTEXT;
  hit.instance = hitGroup.instance;
  hit.primitive = gl_PrimitiveID;
  hit.barycentrics = hitBarycentrics;
  hit.objectOrigin = gl_ObjectRayOriginEXT;
  hit.objectDirection = gl_ObjectRayDirectionEXT;
  hit.objectToWorld = gl_ObjectToWorldEXT;
  hit.worldToObject = gl_WorldToObjectEXT;
  return hit;
}

#endif
