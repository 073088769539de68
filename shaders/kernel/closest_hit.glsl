// closestHit of the direct integrator (equation 2 of the original slides, ../shared/BRDF_SPEC.md):
//   L_o = delta L_i(x, w_r) + (1 - delta) sum_k f_r(w_k, w_o) E_k,   E_k = V_k I_k cos(theta_k) / r_k^2.
// The delta term continues the path along the mirror direction; the raygen loops, nothing recurses.
// Needs `params` (FrameParams) and the scene bindings.
#ifndef RAYLAB_KERNEL_CLOSEST_HIT_GLSL
#define RAYLAB_KERNEL_CLOSEST_HIT_GLSL

#include "brdf/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "kernel/lights.glsl"
#include "kernel/surface.glsl"
#include "kernel/trace.glsl"

// sum_k f_r(w_k, w_o) E_k over every light, with a shadow ray each. ng faces the viewer's side.
vec3 directLighting(vec3 position, vec3 ng, ShadingFrame frame, vec3 woLocal, MaterialRecord material,
                    inout Payload p) {
  vec3 sum = vec3(0.0);
  const vec3 shadowOrigin = offsetRayOrigin(position, ng);
  for (uint k = 0u; k < params.lightCount; ++k) {
    const LightSample light = sampleLight(lights[k], position);
    // Light below the geometric surface cannot reach this side, whatever the shading normal says.
    if (dot(light.wi, ng) <= 0.0) continue;
    const vec3 wiLocal = toLocal(frame, light.wi);
    const vec3 contribution = bsdfEval(material, wiLocal, woLocal) * light.irradiance * wiLocal.z;
    // Only unoccluded light that would contribute is worth a shadow ray.
    if (!(max(contribution.r, max(contribution.g, contribution.b)) > 0.0)) continue;
    p.shadowRays += 1u;
    if (traceVisibility(shadowOrigin, light.wi, light.distance)) sum += contribution;
  }
  return sum;
}

void closestHit(Hit hit, inout Payload p) {
  const Surface s = surfaceAt(hit);
  const MaterialRecord material = materials[s.material];
  const vec3 wo = -p.direction;

  // The BRDFs are one-sided: shade the side the ray arrived on.
  const vec3 ng = s.frontFace ? s.geometricNormal : -s.geometricNormal;
  vec3 ns = s.frontFace ? s.shadingNormal : -s.shadingNormal;
  // Interpolated normals can face away from the viewer near silhouettes; the true surface cannot.
  if (dot(ns, wo) <= 0.0) ns = ng;
  const ShadingFrame frame = makeShadingFrame(ns, s.tangent);

  const float delta = material.delta;
  if (delta < 1.0) {
    p.radiance += p.throughput * (1.0 - delta) * directLighting(s.position, ng, frame, toLocal(frame, wo), material, p);
  }

  p.done = true;
  if (delta > 0.0 && p.depth < params.maxDepth) {
    const vec3 mirror = reflect(p.direction, ns);
    p.throughput *= delta;
    if (dot(mirror, ng) > 0.0 && max(p.throughput.r, max(p.throughput.g, p.throughput.b)) >= params.throughputCutoff) {
      p.origin = offsetRayOrigin(s.position, ng);
      p.direction = mirror;
      p.depth += 1u;
      p.done = false;
    }
  }
}

#endif
