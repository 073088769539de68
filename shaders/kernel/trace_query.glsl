// Traversal with ray queries (the compute backend), shaped like OptiX programs: the intersection program
// intersectSphere decides procedural (sphere) candidates, traceClosest returns the committed hit for
// closestHit, and traceVisibility is the shadow-ray query that stops at the first hit. The pipeline backend's
// counterparts are kernel/trace_pipeline.glsl and the .rgen/.rchit/.rmiss/.rint entry points.
// Needs kernel/scene_bindings.glsl.
#ifndef RAYLAB_KERNEL_TRACE_QUERY_GLSL
#define RAYLAB_KERNEL_TRACE_QUERY_GLSL

#include "kernel/alpha.glsl"
#include "kernel/payload.glsl"
#include "kernel/sphere_program.glsl"

// Without alpha-tested surfaces every triangle is opaque and commits inside the traversal; with them the
// opaque ones still do (their geometry is flagged opaque) and the others come back as candidates.
uint opaqueRayFlag() { return featureEnabled(kFeatureAlpha) ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT; }

// The any-hit program on the query's candidate triangle: confirms it where alphaPasses.
void decideCandidateTriangle(rayQueryEXT query, vec3 origin, vec3 direction) {
  if (alphaPasses(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false),
                  rayQueryGetIntersectionPrimitiveIndexEXT(query, false),
                  rayQueryGetIntersectionBarycentricsEXT(query, false), origin, direction)) {
    rayQueryConfirmIntersectionEXT(query);
  }
}

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
  rayQueryInitializeEXT(query, tlas, opaqueRayFlag(), 0xFFu, origin, tMin, direction, tMax);
  while (rayQueryProceedEXT(query)) {
    // Opaque triangles commit inside the traversal; AABB candidates and alpha-tested triangles come back here.
    if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      float t;
      if (intersectCandidate(query, tMin, committedT(query, tMax), t)) rayQueryGenerateIntersectionEXT(query, t);
    } else {
      decideCandidateTriangle(query, origin, direction);
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
  rayQueryInitializeEXT(query, tlas, opaqueRayFlag() | gl_RayFlagsTerminateOnFirstHitEXT, 0xFFu, origin, 0.0,
                        direction, tMax);
  while (rayQueryProceedEXT(query)) {
    if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionAABBEXT) {
      float t;
      if (intersectCandidate(query, 0.0, tMax, t)) rayQueryGenerateIntersectionEXT(query, t);
    } else {
      decideCandidateTriangle(query, origin, direction);
    }
  }
  return rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT;
}

#endif
