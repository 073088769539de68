// The intersection program of the sphere geometry (OptiX's and Vulkan's intersection shader, not an any-hit:
// it finds the hit; nothing accepts or rejects one). Both backends call it: the ray-query traversal for each
// AABB candidate (kernel/trace_query.glsl), the pipeline from sphere.rint. Needs kernel/scene_bindings.glsl.
#ifndef RAYLAB_KERNEL_SPHERE_PROGRAM_GLSL
#define RAYLAB_KERNEL_SPHERE_PROGRAM_GLSL

#include "kernel/alpha.glsl"
#include "kernel/sphere.glsl"

// The exact sphere test of primitive `primitive` of InstanceRecord `instance`, on the ray in the instance's
// object space (so t is the world-space parameter too). Only t in [tMin, tMax] may be reported, tMax being the
// closest hit committed so far. With the alpha feature a sphere of a partly transparent material (openpbr's
// geometry_opacity) is met at each side with probability its opacity, decided per side (kernel/alpha.glsl): a
// ray that passes the near side may still meet the far one, from inside.
bool intersectSphere(uint instance, uint primitive, vec3 objectOrigin, vec3 objectDirection, float tMin, float tMax,
                     out float t) {
  const SphereRecord sphere = spheres[instances[instance].firstSphere + primitive];
  if (!featureEnabled(kFeatureAlpha)) {
    return nearestSphereHit(objectOrigin, objectDirection, sphere.center, sphere.radius, tMin, tMax, t);
  }
  float tNear, tFar;
  if (!intersectSphere(objectOrigin, objectDirection, sphere.center, sphere.radius, tNear, tFar)) return false;
  const MaterialRecord material = materials[sphere.material];  // the spheres share one instance
  for (uint side = 0u; side < 2u; ++side) {
    const float tSide = side == 0u ? tNear : tFar;
    if (tSide < tMin || tSide > tMax) continue;
    if (coveragePasses(material, 1.0, objectOrigin, objectDirection, instance, primitive, side)) {
      t = tSide;
      return true;
    }
  }
  return false;
}

#endif
