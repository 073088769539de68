// closestHit of the direct integrator (equation 2 of the original slides, docs/brdf_contract.md):
//   L_o = delta L_i(x, w_r) + (1 - delta) sum_k f_r(w_k, w_o) E_k,   E_k = V_k I_k cos(theta_k) / r_k^2.
// The delta term continues the path along the mirror direction. Glass splits into Fresnel-weighted
// reflection and refraction (the delta lobes of bsdfDeltaLobes, brdf/bsdf.glsl). The raygen loops over the
// continuations; nothing recurses. The hit preparation it shares with the path integrator is kernel/hit_common.glsl,
// its lights those of kernel/next_event.glsl. Needs a traceVisibility (kernel/trace_query.glsl or
// kernel/trace_pipeline.glsl, by backend).
#ifndef RAYLAB_KERNEL_CLOSEST_HIT_GLSL
#define RAYLAB_KERNEL_CLOSEST_HIT_GLSL

#include "kernel/aov.glsl"
#include "kernel/hit_common.glsl"
#include "kernel/next_event.glsl"

// Sets the payload's next segment; false when the path should stop there.
bool continuePath(inout Payload p, vec3 origin, vec3 direction, vec3 throughput) {
  if (maxComponent(throughput) < params.throughputCutoff) return false;
  p.path.origin = origin;
  p.path.direction = direction;
  p.path.throughput = throughput;
  return true;
}

// Glass: delta L_i(w_r) + (1 - delta) [F L_i(w_r) + (1 - F) tint L_i(w_t)], both continuations kept. F is
// the exact unpolarised Fresnel term, or Schlick's in the kernel variant that trades accuracy for speed.
void glassHit(Surface s, MaterialRecord material, vec3 wo, inout Payload p) {
  const DeltaLobes lobes = bsdfDeltaLobes(material, wo, s.shadingNormal);
  const float fresnel = lobes.fresnel;
  const float delta = material.delta;
  const bool entering = dot(wo, s.geometricNormal) > 0.0;
  const vec3 weightReflect = p.path.throughput * (delta + (1.0 - delta) * fresnel);
  // The tint colours light once, as it enters: a closed object then tints what is seen through it once.
  const vec3 weightRefract =
      lobes.tir ? vec3(0.0) : p.path.throughput * (1.0 - delta) * (1.0 - fresnel) * (entering ? lobes.transmittance : vec3(1.0));

  // Each continuation leaves from the side of the geometric surface it travels into.
  const vec3 ngOutside = s.geometricNormal;
  const bool reflectOk = dot(lobes.reflected, entering ? ngOutside : -ngOutside) > 0.0;
  const bool refractOk = !lobes.tir && dot(lobes.refracted, entering ? -ngOutside : ngOutside) > 0.0;
  const vec3 reflectOrigin = offsetRayOrigin(s.position, entering ? ngOutside : -ngOutside);
  const vec3 refractOrigin = offsetRayOrigin(s.position, entering ? -ngOutside : ngOutside);

  // The heavier branch continues now; the other waits in the raygen's queue.
  const bool reflectFirst = maxComponent(weightReflect) >= maxComponent(weightRefract);
  p.done = true;
  p.split = false;
  const vec3 origin1 = reflectFirst ? reflectOrigin : refractOrigin;
  const vec3 direction1 = reflectFirst ? lobes.reflected : lobes.refracted;
  const vec3 weight1 = reflectFirst ? weightReflect : weightRefract;
  const bool ok1 = reflectFirst ? reflectOk : refractOk;
  const vec3 origin2 = reflectFirst ? refractOrigin : reflectOrigin;
  const vec3 direction2 = reflectFirst ? lobes.refracted : lobes.reflected;
  const vec3 weight2 = reflectFirst ? weightRefract : weightReflect;
  const bool ok2 = reflectFirst ? refractOk : reflectOk;
  if (ok1 && continuePath(p, origin1, direction1, weight1)) p.done = false;
  if (ok2 && maxComponent(weight2) >= params.throughputCutoff) {
    if (p.done) {
      p.done = !continuePath(p, origin2, direction2, weight2);
    } else {
      p.split = true;
      p.splitOrigin = origin2;
      p.splitDirection = direction2;
      p.splitThroughput = weight2;
    }
  }
}

void closestHit(Hit hit, inout Payload p) {
  Surface s = surfaceAt(hit);
  MaterialRecord material = materials[s.material];
  const vec3 wo = -p.path.direction;
  p.done = true;
  p.split = false;

  if (featureEnabled(kFeatureDeltaBsdf) && isSpecularOnly(bsdfFlags(material))) {
    if (recordsAov(p)) recordAov(p, vec3(1.0), facing(s.shadingNormal, wo));
    if (p.path.depth < params.maxDepth) {
      p.path.depth += 1u;
      glassHit(s, material, wo, p);
    }
    return;
  }
  applyTextures(material, s);
  const float delta = featureEnabled(kFeatureMirror) ? material.delta : 0.0;
  const ShadingSide side = shadingSide(s, wo, bsdfFlags(material), delta);
  const vec3 ng = side.ng;
  const vec3 ns = side.ns;
  const ShadingFrame frame = side.frame;
  applyCoatNormal(material, s, frame);
  if (recordsAov(p)) recordAov(p, firstHitAlbedo(p, material, toLocal(frame, wo), delta), facing(ns, wo));

  // Rough glass (two-sided) sees the lights on both sides of its surface.
  if (delta < 1.0) {
    p.path.radiance += p.path.throughput * (1.0 - delta) * directLighting(s.position, ng, frame, toLocal(frame, wo), material, p);
  }
  if (delta > 0.0 && p.path.depth < params.maxDepth) {
    const vec3 viewerSide = leavingSide(ng, wo);
    const vec3 mirror = reflect(p.path.direction, dot(ns, viewerSide) > 0.0 ? ns : -ns);
    if (dot(mirror, viewerSide) > 0.0 &&
        continuePath(p, offsetRayOrigin(s.position, viewerSide), mirror, p.path.throughput * delta)) {
      p.path.depth += 1u;
      p.done = false;
    }
  }
}

#endif
