// The hit preparation both integrators share (closest_hit.glsl, the slides' integrator, and path_hit.glsl, the
// path integrator): the surface's material with its textures applied, the side of the surface the ray arrived on
// with its shading frame, and next event estimation of the punctual lights. Needs `params` (FrameParams), the
// scene bindings and a traceVisibility (kernel/trace_query.glsl or kernel/trace_pipeline.glsl, by backend).
#ifndef RAYLAB_KERNEL_HIT_COMMON_GLSL
#define RAYLAB_KERNEL_HIT_COMMON_GLSL

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
    p.path.shadowRays += 1u;
    if (traceVisibility(shadowOrigin, light.wi, light.distance)) sum += contribution;
  }
  return sum;
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

#endif
