// Alpha-tested and blended surfaces (glTF 3.9.4, alphaMode MASK and BLEND) as the traversal's candidate test:
// the ray-query loop (kernel/trace_query.glsl) confirms a candidate triangle, and the pipeline's any-hit program
// (alpha.rahit) keeps it, only where alphaPasses. Alpha is MaterialTextures.alpha (baseColorFactor's) times the
// base-colour texture's alpha at the candidate's UV. MASK keeps a hit where alpha >= alphaCutoff, so rays and
// shadow rays pass through the holes (a leaf's shadow is leaf-shaped). BLEND keeps it with probability alpha
// (stochastic transparency): the path integrator's average over samples is the blend; the number is a hash of
// the ray and the primitive, so that an any-hit program run twice for one candidate decides the same, and both
// backends decide alike. A model's opacity (openpbr's geometry_opacity) multiplies the coverage the same way, on
// triangles here and on spheres in their intersection program (kernel/sphere_program.glsl). Only non-opaque
// geometry (meshes of such materials, engine/render/gpu_scene.cpp) comes here.
#ifndef RAYLAB_KERNEL_ALPHA_GLSL
#define RAYLAB_KERNEL_ALPHA_GLSL

#include "common/rng.glsl"
#include "common/specialization.glsl"
#include "kernel/surface.glsl"
#include "kernel/textures.glsl"
#include "generated/model_opacity.glsl"

// A number in [0, 1) fixed by the ray and the surface crossed: an any-hit program run twice for one candidate
// decides the same, and both backends decide alike. `crossing` tells apart two crossings of one primitive (a
// sphere's near and far side).
float coverageCoin(vec3 origin, vec3 direction, uint instanceIndex, uint primitive, uint crossing) {
  const uvec4 h = pcg4d(uvec4(floatBitsToUint(origin.x) ^ floatBitsToUint(direction.z),
                              floatBitsToUint(origin.y) ^ floatBitsToUint(direction.x),
                              floatBitsToUint(origin.z) ^ floatBitsToUint(direction.y),
                              primitive ^ (instanceIndex << 20)));
  // Separate outputs of one hash for the crossings: a flipped top input bit barely reaches the top output bits
  // of a multiplicative hash, and two crossings so keyed met a sphere's far side 7 sigma too often.
  return uintToUnitFloat(crossing == 0u ? h.x : h.y);
}

// True when a ray meets a surface of `material` where its coverage is `alpha` (a BLEND texture's alpha times
// baseColorFactor's, or 1) times the model's opacity (openpbr's geometry_opacity): with that probability.
bool coveragePasses(MaterialRecord material, float alpha, vec3 origin, vec3 direction, uint instanceIndex,
                    uint primitive, uint crossing) {
  const float coverage = alpha * modelOpacity(material);
  return coverage >= 1.0 || coverageCoin(origin, direction, instanceIndex, primitive, crossing) < coverage;
}

// True when the candidate hit on triangle `primitive` of instance record `instanceIndex` counts.
bool alphaPasses(uint instanceIndex, uint primitive, vec2 barycentrics, vec3 origin, vec3 direction) {
  if (!featureEnabled(kFeatureAlpha)) return true;
  const InstanceRecord instance = instances[instanceIndex];
  if (instance.geometryKind != kGeometryTriangles) return true;
  const MaterialRecord material = materials[instance.material];
  const int textures = material.textures;
  const uint mode = textures < 0 ? kAlphaOpaque : materialTextures[textures].alphaMode;
  float alpha = 1.0;
  if (mode != kAlphaOpaque) {
    alpha = materialTextures[textures].alpha;
    const TextureRef base = materialTextures[textures].refs[kTextureBaseColor];
    if (base.texture >= 0) {
      vec2 uv0, uv1;
      triangleUvsAt(instance, primitive, barycentrics, uv0, uv1);
      alpha *= sampleTextureRef(base, uv0, uv1, false).a;  // alpha is linear; only colour is sRGB-encoded
    }
    if (mode == kAlphaMask) {
      if (alpha < materialTextures[textures].alphaCutoff) return false;
      alpha = 1.0;  // a mask's kept part is solid; the model's opacity still applies
    }
  }
  return coveragePasses(material, alpha, origin, direction, instanceIndex, primitive, 0u);
}

#endif
