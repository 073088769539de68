// The hit preparation both integrators share (closest_hit.glsl, the slides' integrator, and path_hit.glsl, the
// path integrator): the surface's material with its textures applied, and the side of the surface the ray
// arrived on with its shading frame. Needs `params` (FrameParams) and the scene bindings.
#ifndef RAYLAB_KERNEL_HIT_COMMON_GLSL
#define RAYLAB_KERNEL_HIT_COMMON_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "brdf/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "common/specialization.glsl"
#include "kernel/surface.glsl"
#include "kernel/textures.glsl"

// A mapped normal makes at least this cosine with the geometric normal.
const float kMinMappedNormalCos = 0.01;

// glTF 3.9.3, normalTexture: the texel's linear RGB is 2 c - 1 in the frame of the tangent, the bitangent
// (cross(normal, tangent) times the tangent's w) and the interpolated normal, x and y scaled by `scale`. Zero where
// the map does not apply: no tangent (an analytic sphere, degenerate UVs), a zero texel.
vec3 mappedNormal(Surface s, TextureRef ref) {
  const vec3 n = s.shadingNormal;
  vec3 t = s.normalTangent.xyz - dot(s.normalTangent.xyz, n) * n;
  if (!(dot(t, t) > 0.0)) return vec3(0.0);
  t = normalize(t);
  const vec3 b = s.normalTangent.w < 0.0 ? -cross(n, t) : cross(n, t);
  vec3 m = sampleTextureRef(ref, s.uv, s.uv1, false).rgb * 2.0 - 1.0;
  m.xy *= ref.scale;
  const vec3 mapped = m.x * t + m.y * b + m.z * n;
  if (!(dot(mapped, mapped) > 1e-12)) return vec3(0.0);
  vec3 ns = normalize(mapped);
  // A normal below the geometric surface (a large scale, a broken map) is tipped back just above it: the
  // shading normal stays on the side of geometricNormal, as Surface promises.
  const vec3 ng = s.geometricNormal;
  const float below = kMinMappedNormalCos - dot(ns, ng);
  if (below > 0.0) ns = normalize(ns + below * ng);
  return ns;
}

void applyNormalMap(inout Surface s, TextureRef ref) {
  const vec3 ns = mappedNormal(s, ref);
  if (!(dot(ns, ns) > 0.0)) return;
  s.shadingNormal = ns;
  s.normalMapped = true;
}

// The coat's own normal map (applyTextures) in the shading frame: geometry_coat_normal_x and _y of the coat, at each
// hit (openpbr's coat is shaded in that frame). A frame turned to the back face turns the coat's normal with it.
void applyCoatNormal(inout MaterialRecord material, Surface s, ShadingFrame frame) {
  if (!(featureEnabled(kFeatureLayerTextures) && dot(s.coatNormal, s.coatNormal) > 0.0)) return;
  const uint slot = materialTextures[material.textures].refs[kTextureCoatNormal].param;
  const vec3 n = dot(s.coatNormal, frame.n) < 0.0 ? -s.coatNormal : s.coatNormal;
  material.params[slot] = dot(n, frame.t);
  material.params[slot + 1u] = dot(n, frame.b);
}

// glTF's anisotropy texel (KHR_materials_anisotropy, KHR_materials_coat): its B scales the strength, mapped onto
// openpbr's ratio as the loader maps the factor (gltf_materials.cpp, anisotropyOf) at this roughness; returns the
// turn its RG direction gives, from the tangent towards the bitangent (a texel of (0.5, 0.5) has no direction: 0).
float applyAnisotropyTexel(inout MaterialRecord material, vec3 texel, float strengthFactor, uint ratioSlot,
                           float roughness) {
  const float alpha = max(roughness * roughness, 1e-3);
  const float strength = strengthFactor * texel.b;
  material.params[ratioSlot] = clamp(1.0 - alpha / (alpha + (1.0 - alpha) * strength * strength), 0.0, 1.0);
  const vec2 direction = 2.0 * texel.rg - 1.0;
  return dot(direction, direction) > 0.0 ? atan(direction.y, direction.x) : 0.0;
}

// KHR_materials_coat's coat anisotropy texture (kTextureCoatAnisotropy): the coat's strength and its turn from the
// shading frame's tangent, which the base's texel (baseTurn) has already turned.
void applyCoatAnisotropy(inout MaterialRecord material, Surface s, MaterialTextures uses, float baseTurn) {
  const TextureRef coat = uses.refs[kTextureCoatAnisotropy];
  if (coat.param == 0u) return;
  const uint ratioSlot = coat.param & 0xFFu, roughnessSlot = (coat.param >> 8u) & 0xFFu;
  const uint angleSlot = (coat.param >> 16u) & 0xFFu;
  float turn = -baseTurn;
  if (coat.texture >= 0) {
    turn += applyAnisotropyTexel(material, sampleTextureRef(coat, s.uv, s.uv1, false).rgb, coat.scale, ratioSlot,
                                 material.params[roughnessSlot]);
  }
  material.params[angleSlot] += turn;
}

// KHR_materials_anisotropy's direction: the tangent turned by anisotropyRotation plus the texture's angle (its RG, in
// the frame of the tangent and the bitangent cross(n, t) w) about the shading normal; the texture's B scales the
// strength. The shading frame's x axis is the tangent (shadingSide), and the anisotropic GGX stretches along it.
void applyAnisotropyDirection(inout MaterialRecord material, inout Surface s, MaterialTextures uses) {
  const TextureRef anisotropy = uses.refs[kTextureAnisotropy];
  float texelTurn = 0.0;
  if (anisotropy.texture >= 0) {
    const uint roughnessSlot = material.textureParams & 0xFFu;
    texelTurn = applyAnisotropyTexel(material, sampleTextureRef(anisotropy, s.uv, s.uv1, false).rgb, anisotropy.scale,
                                     anisotropy.param,
                                     roughnessSlot != kNoTextureParam ? material.params[roughnessSlot] : 0.0);
  }
  applyCoatAnisotropy(material, s, uses, texelTurn);
  const float angle = uses.anisotropyRotation + texelTurn;
  const vec3 n = s.shadingNormal;
  const vec3 t = s.tangent - n * dot(n, s.tangent);
  if (angle == 0.0 || !(dot(t, t) > 0.0)) return;
  const vec3 tangent = normalize(t);
  const float handedness = s.normalTangent.w < 0.0 ? -1.0 : 1.0;
  s.tangent = cos(angle) * tangent + sin(angle) * handedness * cross(n, tangent);
}

// The material's textures (MaterialTextures): the base colour multiplies the model's diffuse colour (the
// parameter of its `diffuse` role), the metallic-roughness texture's G and B its roughness and metallic
// parameters (roles `roughness`, `metallic`), KHR_materials_specular's textures its A and RGB the specular
// strength and colour (roles `specular_weight`, `specular_tint`), the layered extensions' textures the layer
// parameters they name (kTextureCoat...), and the normal map bends the shading normal.
// The emissive texture is read where emission is (kernel/emission.glsl).
void applyTextures(inout MaterialRecord material, inout Surface s) {
  if (!featureEnabled(kFeatureTextures) || material.textures < 0) return;
  const MaterialTextures uses = materialTextures[material.textures];
  const TextureRef base = uses.refs[kTextureBaseColor];
  if (base.texture >= 0 && material.diffuseParam != kNoParam) {
    const vec3 texel = sampleTextureRef(base, s.uv, s.uv1, true).rgb;
    const uint slot = material.diffuseParam;
    material.params[slot] *= texel.r;
    material.params[slot + 1u] *= texel.g;
    material.params[slot + 2u] *= texel.b;
  }
  const TextureRef metallicRoughness = uses.refs[kTextureMetallicRoughness];
  if (metallicRoughness.texture >= 0) {
    const vec4 texel = sampleTextureRef(metallicRoughness, s.uv, s.uv1, false);
    const uint roughness = material.textureParams & 0xFFu;
    const uint metallic = (material.textureParams >> 8u) & 0xFFu;
    if (roughness != kNoTextureParam) material.params[roughness] *= texel.g;
    if (metallic != kNoTextureParam) material.params[metallic] *= texel.b;
  }
  const TextureRef specular = uses.refs[kTextureSpecular];
  const uint specularSlot = (material.textureParams >> 16u) & 0xFFu;
  if (specular.texture >= 0 && specularSlot != kNoTextureParam) {
    material.params[specularSlot] *= sampleTextureRef(specular, s.uv, s.uv1, false).a;
  }
  const TextureRef specularColor = uses.refs[kTextureSpecularColor];
  const uint tintSlot = material.textureParams >> 24u;
  if (specularColor.texture >= 0 && tintSlot != kNoTextureParam) {
    const vec3 texel = sampleTextureRef(specularColor, s.uv, s.uv1, true).rgb;
    material.params[tintSlot] *= texel.r;
    material.params[tintSlot + 1u] *= texel.g;
    material.params[tintSlot + 2u] *= texel.b;
  }
  if (featureEnabled(kFeatureLayerTextures) && uses.layerModel == material.model) {
    // One texture read in a loop kept rolled, not one inlined per use (the feature still costs a textured openpbr
    // kernel about a third more compile time: ClearCoatTest 72 -> 95 s cold).
    [[dont_unroll]] for (uint use = kFirstLayerTexture; use < kLayerTexturesEnd; ++use) {
      const TextureRef layer = uses.refs[use];
      if (layer.texture < 0) continue;
      const bool colour =
          use == kTextureSheenColor || use == kTextureCoatColor || use == kTextureDiffuseTransmissionColor;
      const vec4 texel = sampleTextureRef(layer, s.uv, s.uv1, colour);
      if (colour) {
        material.params[layer.param] *= texel.r;
        material.params[layer.param + 1u] *= texel.g;
        material.params[layer.param + 2u] *= texel.b;
        continue;
      }
      // Each extension's channel: R for weights, G for roughness and thickness, A for the sheen's roughness and
      // the diffuse transmission.
      const float t = use == kTextureCoatRoughness || use == kTextureIridescenceThickness      ? texel.g
                      : use == kTextureSheenRoughness || use == kTextureDiffuseTransmission ? texel.a
                                                                                              : texel.r;
      material.params[layer.param] *= layer.scale + (1.0 - layer.scale) * t;
    }
    applyAnisotropyDirection(material, s, uses);
    // The coat's map is read in the interpolated normal's frame, as the base's: before the base's bends it.
    const TextureRef coatNormal = uses.refs[kTextureCoatNormal];
    if (coatNormal.texture >= 0) s.coatNormal = mappedNormal(s, coatNormal);
  }
  const TextureRef normal = uses.refs[kTextureNormal];
  if (normal.texture >= 0) applyNormalMap(s, normal);
}

// A mapped shading normal bent towards ng just enough that the mirror direction of wo about it stays above the
// geometric surface, by min(0.9 cos, 0.01) of wo's own elevation (the condition of Blender Cycles'
// ensure_valid_reflection, solved here by bisection on the blend towards ng): a map that tilts the normal
// away from the viewer otherwise sends reflections into the surface, where they are refused and the
// surface darkens at grazing angles. ng faces wo. Only a BSDF that reflects about the normal needs it (a glossy
// or delta lobe, or the mirror weight): a diffuse one shades with the mapped normal as it is, as Cycles bends
// the normal of its glossy closures only.
vec3 validReflectionNormal(vec3 ns, vec3 ng, vec3 wo) {
  const float threshold = min(0.9 * dot(ng, wo), 0.01);
  if (dot(reflect(-wo, ns), ng) >= threshold) return ns;
  float low = 0.0, high = 1.0;  // the blend at `high` always satisfies it: reflect(-wo, ng).ng = wo.ng
  for (int i = 0; i < 12; ++i) {
    const float middle = 0.5 * (low + high);
    if (dot(reflect(-wo, normalize(mix(ns, ng, middle))), ng) >= threshold) high = middle;
    else low = middle;
  }
  return normalize(mix(ns, ng, high));
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

ShadingSide shadingSide(Surface s, vec3 wo, uint flags, float delta) {
  ShadingSide side;
  const bool flip = !isTwoSided(flags) && !s.frontFace;
  side.ng = flip ? -s.geometricNormal : s.geometricNormal;
  side.ns = flip ? -s.shadingNormal : s.shadingNormal;
  // Interpolated normals can put the viewer on the other side of the shading normal near silhouettes; the true
  // surface cannot.
  const bool reflects = (flags & (kLobeGlossy | kLobeSpecular)) != 0u || delta > 0.0;
  if (s.normalMapped && reflects && dot(side.ng, wo) > 0.0) side.ns = validReflectionNormal(side.ns, side.ng, wo);
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
