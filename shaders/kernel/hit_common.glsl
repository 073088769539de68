// The hit preparation both integrators share (closest_hit.glsl, the slides' integrator, and path_hit.glsl, the
// path integrator): the surface's material with its textures applied, and the side of the surface the ray
// arrived on with its shading frame. Needs `params` (FrameParams) and the scene bindings.
#ifndef RAYLAB_KERNEL_HIT_COMMON_GLSL
#define RAYLAB_KERNEL_HIT_COMMON_GLSL

#include "brdf/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "common/specialization.glsl"
#include "kernel/surface.glsl"
#include "kernel/textures.glsl"

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
