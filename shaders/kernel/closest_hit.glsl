// closestHit of the direct integrator (equation 2 of the original slides, docs/brdf_contract.md):
//   L_o = delta L_i(x, w_r) + (1 - delta) sum_k f_r(w_k, w_o) E_k,   E_k = V_k I_k cos(theta_k) / r_k^2.
// The delta term continues the path along the mirror direction. Glass splits into Fresnel-weighted
// reflection and refraction (exact Fresnel, total internal reflection, optional tint). The raygen loops over
// the continuations; nothing recurses. Needs `params` (FrameParams), the scene bindings and a traceVisibility
// (kernel/trace_query.glsl or kernel/trace_pipeline.glsl, by backend).
#ifndef RAYLAB_KERNEL_CLOSEST_HIT_GLSL
#define RAYLAB_KERNEL_CLOSEST_HIT_GLSL

#include "brdf/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "common/specialization.glsl"
#include "kernel/lights.glsl"
#include "kernel/surface.glsl"
#include "kernel/textures.glsl"

// A light as it is in the world this frame: a headlight's offset in the camera's frame made a position.
LightRecord placedLight(LightRecord light) {
  if (featureEnabled(kFeatureHeadlight) && light.type == kLightHeadlight) {
    light.position = params.cameraOrigin + light.position.x * normalize(params.cameraRight) +
                     light.position.y * normalize(params.cameraUp) + light.position.z * params.cameraForward;
  }
  return light;
}

// sum_k f_r(w_k, w_o) E_k over every light, with a shadow ray each. ng faces the viewer's side.
vec3 directLighting(vec3 position, vec3 ng, ShadingFrame frame, vec3 woLocal, MaterialRecord material,
                    inout Payload p) {
  vec3 sum = vec3(0.0);
  const vec3 shadowOrigin = offsetRayOrigin(position, ng);
  for (uint k = 0u; k < params.lightCount; ++k) {
    const LightSample light = sampleLight(placedLight(lights[k]), position);
    // Light below the geometric surface cannot reach this side, whatever the shading normal says.
    if (dot(light.wi, ng) <= 0.0) continue;
    const vec3 wiLocal = toLocal(frame, light.wi);
    const vec3 contribution = bsdfEval(material, wiLocal, woLocal) * light.irradiance * wiLocal.z;
    // Only light that would contribute is worth a shadow ray.
    if (!(maxComponent(contribution) > 0.0)) continue;
    p.shadowRays += 1u;
    if (traceVisibility(shadowOrigin, light.wi, light.distance)) sum += contribution;
  }
  return sum;
}

// Sets the payload's next segment; false when the path should stop there.
bool continuePath(inout Payload p, vec3 origin, vec3 direction, vec3 throughput) {
  if (maxComponent(throughput) < params.throughputCutoff) return false;
  p.origin = origin;
  p.direction = direction;
  p.throughput = throughput;
  return true;
}

// Glass: delta L_i(w_r) + (1 - delta) [F L_i(w_r) + (1 - F) tint L_i(w_t)], both continuations kept. F is
// the exact unpolarised Fresnel term, or Schlick's in the kernel variant that trades accuracy for speed.
void glassHit(Surface s, MaterialRecord material, vec3 wo, inout Payload p) {
  const DeltaEvent event = modelDeltaEvent(material, wo, s.shadingNormal);
  // The kernel variant picks the Fresnel term; the other one's arithmetic is dead code and compiles away.
  const float fresnel = kGlassFresnel == kFresnelSchlick ? event.fresnelSchlick : event.fresnelExact;
  const float delta = material.delta;
  const bool entering = dot(wo, s.geometricNormal) > 0.0;
  const vec3 weightReflect = p.throughput * (delta + (1.0 - delta) * fresnel);
  // The tint colours light once, as it enters: a closed object then tints what is seen through it once.
  const vec3 weightRefract =
      event.tir ? vec3(0.0) : p.throughput * (1.0 - delta) * (1.0 - fresnel) * (entering ? event.transmittance : vec3(1.0));

  // Each continuation leaves from the side of the geometric surface it travels into.
  const vec3 ngOutside = s.geometricNormal;
  const bool reflectOk = dot(event.reflected, entering ? ngOutside : -ngOutside) > 0.0;
  const bool refractOk = !event.tir && dot(event.refracted, entering ? -ngOutside : ngOutside) > 0.0;
  const vec3 reflectOrigin = offsetRayOrigin(s.position, entering ? ngOutside : -ngOutside);
  const vec3 refractOrigin = offsetRayOrigin(s.position, entering ? -ngOutside : ngOutside);

  // The heavier branch continues now; the other waits in the raygen's queue.
  const bool reflectFirst = maxComponent(weightReflect) >= maxComponent(weightRefract);
  p.done = true;
  p.split = false;
  const vec3 origin1 = reflectFirst ? reflectOrigin : refractOrigin;
  const vec3 direction1 = reflectFirst ? event.reflected : event.refracted;
  const vec3 weight1 = reflectFirst ? weightReflect : weightRefract;
  const bool ok1 = reflectFirst ? reflectOk : refractOk;
  const vec3 origin2 = reflectFirst ? refractOrigin : reflectOrigin;
  const vec3 direction2 = reflectFirst ? event.refracted : event.reflected;
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

// The base-colour texture, which multiplies the model's diffuse colour (the parameter of its `diffuse` role).
void applyTextures(inout MaterialRecord material, Surface s) {
  if (featureEnabled(kFeatureTextures) && material.baseColorTexture >= 0 && material.diffuseParam != kNoParam) {
    const vec3 texel = sampleTexture(uint(material.baseColorTexture), s.uv).rgb;
    const uint slot = material.diffuseParam;
    material.params[slot] *= texel.r;
    material.params[slot + 1u] *= texel.g;
    material.params[slot + 2u] *= texel.b;
  }
}

// The side of the surface the ray arrived on, which the one-sided BRDFs shade: its geometric normal ng, the
// shading normal ns and the local frame around ns.
struct ShadingSide {
  vec3 ng;
  vec3 ns;
  ShadingFrame frame;
};

ShadingSide shadingSide(Surface s, vec3 wo) {
  ShadingSide side;
  side.ng = s.frontFace ? s.geometricNormal : -s.geometricNormal;
  side.ns = s.frontFace ? s.shadingNormal : -s.shadingNormal;
  // Interpolated normals can face away from the viewer near silhouettes; the true surface cannot.
  if (dot(side.ns, wo) <= 0.0) side.ns = side.ng;
  side.frame = makeShadingFrame(side.ns, s.tangent);
  return side;
}

void closestHit(Hit hit, inout Payload p) {
  const Surface s = surfaceAt(hit);
  MaterialRecord material = materials[s.material];
  const vec3 wo = -p.direction;
  p.done = true;
  p.split = false;

  if (featureEnabled(kFeatureDeltaBsdf) && isSpecularOnly(bsdfFlags(material))) {
    if (p.depth < params.maxDepth) {
      p.depth += 1u;
      glassHit(s, material, wo, p);
    }
    return;
  }
  applyTextures(material, s);
  const ShadingSide side = shadingSide(s, wo);
  const vec3 ng = side.ng;
  const vec3 ns = side.ns;
  const ShadingFrame frame = side.frame;

  const float delta = featureEnabled(kFeatureMirror) ? material.delta : 0.0;
  if (delta < 1.0) {
    p.radiance += p.throughput * (1.0 - delta) * directLighting(s.position, ng, frame, toLocal(frame, wo), material, p);
  }
  if (delta > 0.0 && p.depth < params.maxDepth) {
    const vec3 mirror = reflect(p.direction, ns);
    if (dot(mirror, ng) > 0.0 && continuePath(p, offsetRayOrigin(s.position, ng), mirror, p.throughput * delta)) {
      p.depth += 1u;
      p.done = false;
    }
  }
}

#endif
