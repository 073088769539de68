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

// The side of the surface a BSDF is shaded on, and its frame. A one-sided BRDF is shaded on the side the ray
// arrived on: ng and ns face the viewer. A two-sided BSDF (rough glass, isTwoSided) sees both sides in the frame
// of the outward normal: ng and ns are the outward ones, and woLocal.z < 0 means the viewer is inside.
// Either way a direction w is usable only where the geometric and the shading normal agree on its side
// (seesSameSide), and a ray towards w leaves from the side w points to (leavingSide).
struct ShadingSide {
  vec3 ng;
  vec3 ns;
  ShadingFrame frame;
};

ShadingSide shadingSide(Surface s, vec3 wo, uint flags) {
  ShadingSide side;
  const bool flip = !isTwoSided(flags) && !s.frontFace;
  side.ng = flip ? -s.geometricNormal : s.geometricNormal;
  side.ns = flip ? -s.shadingNormal : s.shadingNormal;
  // Interpolated normals can put the viewer on the other side of the shading normal near silhouettes; the true
  // surface cannot.
  if (dot(side.ns, wo) * dot(side.ng, wo) <= 0.0) side.ns = side.ng;
  side.frame = makeShadingFrame(side.ns, s.tangent);
  return side;
}

// True when w lies on the same side of the geometric normal ng as its local z (wLocal.z) says it does of the
// shading normal: light the geometric surface blocks, or a sample that would leak through it, is refused.
bool seesSameSide(vec3 w, vec3 ng, float wLocalZ) { return dot(w, ng) * wLocalZ > 0.0; }

// The geometric normal on the side w points to: where a ray towards w starts (offsetRayOrigin).
vec3 leavingSide(vec3 ng, vec3 w) { return dot(w, ng) > 0.0 ? ng : -ng; }

#endif
