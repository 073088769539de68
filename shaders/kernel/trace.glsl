// Traversal with ray queries, shaped like OptiX programs: the intersection program intersectSphere decides
// procedural (sphere) candidates, traceClosest returns the committed hit for closestHit, and traceVisibility is
// the shadow-ray query that stops at the first hit. Needs kernel/scene_bindings.glsl.
#ifndef RAYLAB_KERNEL_TRACE_GLSL
#define RAYLAB_KERNEL_TRACE_GLSL

#include "kernel/payload.glsl"
#include "kernel/sphere.glsl"

// The intersection program of AABB candidates (OptiX's and Vulkan's intersection shader, not an any-hit: it
// finds the hit; nothing accepts or rejects one): the exact sphere test in the instance's object space. Only t
// in [tMin, tMax] may be reported (tMax: the current committed hit), as rayQueryGenerateIntersectionEXT requires.
bool intersectSphere(rayQueryEXT query, float tMin, float tMax, out float t) {
  const uint instance = rayQueryGetIntersectionInstanceCustomIndexEXT(query, false);
  const uint primitive = rayQueryGetIntersectionPrimitiveIndexEXT(query, false);
  const SphereRecord sphere = spheres[instances[instance].firstSphere + primitive];
  const vec3 origin = rayQueryGetIntersectionObjectRayOriginEXT(query, false);
  const vec3 direction = rayQueryGetIntersectionObjectRayDirectionEXT(query, false);
  return nearestSphereHit(origin, direction, sphere.center, sphere.radius, tMin, tMax, t);
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
      if (intersectSphere(query, tMin, committedT(query, tMax), t)) rayQueryGenerateIntersectionEXT(query, t);
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
      if (intersectSphere(query, 0.0, tMax, t)) rayQueryGenerateIntersectionEXT(query, t);
    }
  }
  return rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT;
}

#endif
