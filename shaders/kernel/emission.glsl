// Emitted radiance L_e at a point of an emitting surface, the one function both the continuation that reaches an
// emitter (path_hit.glsl) and next event estimation (lights/triangle.glsl) evaluate, so that their MIS weights
// meet the same value: the material's emission (emissiveFactor x KHR_materials_emissive_strength) times its
// emissive texture (glTF 2.0 3.9.3), an sRGB colour.
#ifndef RAYLAB_KERNEL_EMISSION_GLSL
#define RAYLAB_KERNEL_EMISSION_GLSL

#include "common/specialization.glsl"
#include "kernel/textures.glsl"
#include "generated/model_opacity.glsl"

vec3 emittedRadiance(MaterialRecord material, vec2 uv0, vec2 uv1) {
  vec3 radiance = material.emission;
  if (featureEnabled(kFeatureTextures) && material.textures >= 0) {
    const TextureRef emissive = materialTextures[material.textures].refs[kTextureEmissive];
    if (emissive.texture >= 0) radiance *= sampleTextureRef(emissive, uv0, uv1, true).rgb;
  }
  return radiance;
}

// The radiance next event estimation carries from a point of a partly covered emitter (openpbr's geometry_opacity):
// L_e times the coverage. Its shadow ray stops short of the emitter and never draws the emitter's own coverage coin,
// where a ray that reaches the emitter meets it with that probability; both then see coverage x L_e on average.
// Untextured emitters carry it in their light record (engine/render/light_records.cpp).
vec3 coveredEmittedRadiance(MaterialRecord material, vec2 uv0, vec2 uv1) {
  return emittedRadiance(material, uv0, uv1) * (featureEnabled(kFeatureAlpha) ? modelOpacity(material) : 1.0);
}

#endif
