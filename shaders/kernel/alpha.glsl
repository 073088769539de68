// Alpha-tested and blended surfaces (glTF 3.9.4, alphaMode MASK and BLEND) as the traversal's candidate test:
// the ray-query loop (kernel/trace_query.glsl) confirms a candidate triangle, and the pipeline's any-hit program
// (alpha.rahit) keeps it, only where alphaPasses. Alpha is MaterialTextures.alpha (baseColorFactor's) times the
// base-colour texture's alpha at the candidate's UV. MASK keeps a hit where alpha >= alphaCutoff, so rays and
// shadow rays pass through the holes (a leaf's shadow is leaf-shaped). BLEND keeps it with probability alpha
// (stochastic transparency): the path integrator's average over samples is the blend; the number is a hash of
// the ray and the primitive, so that an any-hit program run twice for one candidate decides the same, and both
// backends decide alike. Only non-opaque geometry (meshes of such materials, engine/render/gpu_scene.cpp) comes
// here; analytic spheres are always opaque.
#ifndef RAYLAB_KERNEL_ALPHA_GLSL
#define RAYLAB_KERNEL_ALPHA_GLSL

#include "common/rng.glsl"
#include "common/specialization.glsl"
#include "kernel/surface.glsl"
#include "kernel/textures.glsl"

// True when the candidate hit on triangle `primitive` of instance record `instanceIndex` counts.
bool alphaPasses(uint instanceIndex, uint primitive, vec2 barycentrics, vec3 origin, vec3 direction) {
  if (!featureEnabled(kFeatureAlpha)) return true;
  const InstanceRecord instance = instances[instanceIndex];
  if (instance.geometryKind != kGeometryTriangles) return true;
  const int textures = materials[instance.material].textures;
  if (textures < 0) return true;
  const uint mode = materialTextures[textures].alphaMode;
  if (mode == kAlphaOpaque) return true;
  float alpha = materialTextures[textures].alpha;
  const TextureRef base = materialTextures[textures].refs[kTextureBaseColor];
  if (base.texture >= 0) {
    vec2 uv0, uv1;
    triangleUvsAt(instance, primitive, barycentrics, uv0, uv1);
    alpha *= sampleTextureRef(base, uv0, uv1, false).a;  // alpha is linear; only colour is sRGB-encoded
  }
  if (mode == kAlphaMask) return alpha >= materialTextures[textures].alphaCutoff;
  const uvec4 h = pcg4d(uvec4(floatBitsToUint(origin.x) ^ floatBitsToUint(direction.z),
                              floatBitsToUint(origin.y) ^ floatBitsToUint(direction.x),
                              floatBitsToUint(origin.z) ^ floatBitsToUint(direction.y), primitive ^ (instanceIndex << 20)));
  return uintToUnitFloat(h.x) < alpha;
}

#endif
