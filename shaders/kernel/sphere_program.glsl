// The intersection program of the sphere geometry (OptiX's and Vulkan's intersection shader, not an any-hit:
// it finds the hit; nothing accepts or rejects one). Both backends call it: the ray-query traversal for each
// AABB candidate (kernel/trace_query.glsl), the pipeline from sphere.rint. Needs kernel/scene_bindings.glsl.
#ifndef RAYLAB_KERNEL_SPHERE_PROGRAM_GLSL
#define RAYLAB_KERNEL_SPHERE_PROGRAM_GLSL

#include "kernel/sphere.glsl"

// The exact sphere test of primitive `primitive` of InstanceRecord `instance`, on the ray in the instance's
// object space (so t is the world-space parameter too). Only t in [tMin, tMax] may be reported, tMax being the
// closest hit committed so far.
bool intersectSphere(uint instance, uint primitive, vec3 objectOrigin, vec3 objectDirection, float tMin, float tMax,
                     out float t) {
  const SphereRecord sphere = spheres[instances[instance].firstSphere + primitive];
  return nearestSphereHit(objectOrigin, objectDirection, sphere.center, sphere.radius, tMin, tMax, t);
}

#endif
