// Traversal with ray queries (the compute backend), shaped like OptiX programs: the intersection program
// intersectSphere decides procedural (sphere) candidates, traceClosest returns the committed hit for
// closestHit, and traceVisibility is the shadow-ray query that stops at the first hit. The pipeline backend's
// counterparts are kernel/trace_pipeline.glsl and the .rgen/.rchit/.rmiss/.rint entry points.
// Needs kernel/scene_bindings.glsl.
#ifndef RAYLAB_KERNEL_TRACE_QUERY_GLSL
#define RAYLAB_KERNEL_TRACE_QUERY_GLSL

#include "kernel/payload.glsl"
#include "kernel/sphere_program.glsl"

// The intersection program on the query's AABB candidate.
bool intersectCandidate(rayQueryEXT query, float tMin, float tMax, out float t) {
  return intersectSphere(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false),
                         rayQueryGetIntersectionPrimitiveIndexEXT(query, false),
                         rayQueryGetIntersectionObjectRayOriginEXT(query, false),
                         rayQueryGetIntersectionObjectRayDirectionEXT(query, false), tMin, tMax, t);
}

float committedT(rayQueryEXT query, float tMax) {
  return rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT
             ? tMax
             : rayQueryGetIntersectionTEXT(query, true);
}

// The closest hit along the ray in [tMin, tMax]; false on a miss.
bool traceClosest(vec3 origin, vec3 direction, float tMin, float tMax, out Hit hit) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, tlas, gl_RayFlagsOpaqueEXT, 0xFFu, origin, tMin, direction, tMax);
  while (rayQueryProceedEXT(query)) {
    // Opaque triangles commit inside the traversal; only AABB candidates come back here.
    if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      float t;
      if (intersectCandidate(query, tMin, committedT(query, tMax), t)) rayQueryGenerateIntersectionEXT(query, t);
    }
  }
  const uint type = rayQueryGetIntersectionTypeEXT(query, true);
  if (type == gl_RayQueryCommittedIntersectionNoneEXT) return false;  // nothing committed may be read now
  hit.t = rayQueryGetIntersectionTEXT(query, true);
  hit.instance = rayQueryGetIntersectionInstanceCustomIndexEXT(query, true);
  hit.primitive = rayQueryGetIntersectionPrimitiveIndexEXT(query, true);
  hit.barycentrics = type == gl_RayQueryCommittedIntersectionTriangleEXT
                         ? rayQueryGetIntersectionBarycentricsEXT(query, true)
                         : vec2(0.0);
  hit.objectOrigin = rayQueryGetIntersectionObjectRayOriginEXT(query, true);
  hit.objectDirection = rayQueryGetIntersectionObjectRayDirectionEXT(query, true);
  hit.objectToWorld = rayQueryGetIntersectionObjectToWorldEXT(query, true);
  hit.worldToObject = rayQueryGetIntersectionWorldToObjectEXT(query, true);
  return true;
}

// True when nothing lies on the ray in [0, tMax]: the shadow ray, terminated by its first hit.
bool traceVisibility(vec3 origin, vec3 direction, float tMax) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, tlas, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT, 0xFFu, origin, 0.0,
                        direction, tMax);
  while (rayQueryProceedEXT(query)) {
    if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      float t;
      if (intersectCandidate(query, 0.0, tMax, t)) rayQueryGenerateIntersectionEXT(query, t);
    }
  }
  return rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT;
}

#endif
