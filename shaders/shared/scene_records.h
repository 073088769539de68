// Scene data as the kernels see it: instances, geometry, materials and lights.
#ifndef RAYLAB_SHARED_SCENE_RECORDS_H
#define RAYLAB_SHARED_SCENE_RECORDS_H

#include "compat.h"
#include "generated/light_kinds.h"

RL_NAMESPACE_BEGIN

// InstanceRecord.geometryKind
RL_CONST uint kGeometryTriangles = 0;
RL_CONST uint kGeometrySpheres = 1;  // AABB BLAS; primitive i is SphereRecord firstSphere + i

// InstanceRecord.vertexFlags
RL_CONST uint kVertexHasNormals = 1;
RL_CONST uint kVertexHasUvs = 2;
RL_CONST uint kVertexHasUvs1 = 4;      // TEXCOORD_1 (binding kBindingUvs1)
RL_CONST uint kVertexHasTangents = 8;  // glTF TANGENT, or generated for a normal map (binding kBindingTangents)

// One per TLAS instance; the TLAS instance custom index is this record's index.
struct InstanceRecord {
  uint geometryKind;
  uint material;     // triangles: material of the whole mesh
  uint firstIndex;   // triangles: first entry of this mesh in the index buffer
  uint firstVertex;  // triangles: added to every index of this mesh
  uint firstSphere;  // spheres: record of primitive 0
  uint vertexFlags;
  uint firstLight;  // LightRecord of primitive 0 when the instance emits, else kNoLight
};
RL_CHECK_SIZE(InstanceRecord, 28);

RL_CONST uint kNoLight = 0xFFFFFFFFu;
RL_CONST uint kNoInstance = 0xFFFFFFFFu;

// The environment image (binding kBindingEnvironment): this header, then `data`, floats in four arrays of the
// image's texels, rows from the top: linear RGB (3 per texel), then the sampling density f (luminance times
// sin(theta), 1 per texel), its inclusive cdf along each row normalised to 1 per row (1 per texel), and the
// inclusive cdf over rows (1 per row). Directions have pdf f / fMean / (2 pi^2 sin theta) per unit solid angle
// (docs/integrators.md, "Environment light").
struct EnvironmentHeader {
  uint width;   // 0: no image (the scene's uniform background)
  uint height;
  float fMean;  // mean of f over the texels; 0: nothing to sample
  uint light;   // the LightRecord that samples the image, or kNoLight
};
RL_CHECK_SIZE(EnvironmentHeader, 16);

// An analytic sphere in the object space of its instance.
struct SphereRecord {
  vec3 center;
  float radius;
  uint material;
};
RL_CHECK_SIZE(SphereRecord, 20);

// The parameters of a material's model, in the order of its GLSL table (shaders/brdf/<model>.glsl), an RGB
// parameter taking three floats. The model registry assigns each parameter its slot (docs/extending.md).
RL_CONST uint kMaxMaterialParams = 52;  // at most 52: BrdfSampleParams (a MaterialRecord in it) is a 256-byte push constant
RL_CONST uint kNoParam = 0xFFFFFFFFu;

struct MaterialRecord {
  uint model;             // registry id: the order of shaders/brdf/models.cmake
  float delta;            // mirror-reflection weight of the direct integrator
  int textures;           // -1: none; else its MaterialTextures record (binding kBindingMaterialTextures)
  uint diffuseParam;      // slot of the model's diffuse colour (its `diffuse` role), kNoParam without one
  vec3 emission;          // emitted radiance L_e (linear RGB) from the front face; the path integrator shows it
  uint textureParams;     // slots textures scale, by role, kNoTextureParam in any without one: roughness
                          // (bits 0-7) and metallic (8-15) by the metallic-roughness texture, specular_weight
                          // (16-23) and specular_tint's first (24-31) by KHR_materials_specular's
  float params[kMaxMaterialParams];
};
RL_CHECK_SIZE(MaterialRecord, 240);
RL_CONST uint kNoTextureParam = 0xFFu;

// TextureRecord.wrap: bits 0-1 for s (u), bits 2-3 for t (v), as glTF samplers define them.
RL_CONST uint kWrapRepeat = 0;
RL_CONST uint kWrapClamp = 1;
RL_CONST uint kWrapMirror = 2;

// TextureRecord.wrap bit 4: magnification by the nearest texel (glTF magFilter NEAREST) instead of bilinear.
RL_CONST uint kFilterNearest = 16;
// TextureRecord.wrap bit 5: RGBA16 texels, two words each (R | G << 16, B | A << 16), instead of one RGBA8 word.
RL_CONST uint kTexels16 = 32;

// A texture: RGBA8 (or RGBA16) texels as the file stores them, rows from the top. Whether they are sRGB-encoded
// colour (base colour, emissive) or linear data (metallic-roughness, normals) is the use's (TextureRef), so one
// image is decoded once and shared by every use.
struct TextureRecord {
  uint firstTexel;  // its first word in the texel buffer
  uint width;
  uint height;
  uint wrap;        // the wrap modes, kFilterNearest and kTexels16
};
RL_CHECK_SIZE(TextureRecord, 16);

// One use of a texture by a material (glTF textureInfo): the UV set, KHR_texture_transform as the affine map
// uv' = (dot(row0, (u, v, 1)), dot(row1, (u, v, 1))), and normalTexture.scale.
struct TextureRef {
  int texture;    // TextureRecord index; -1: none
  uint texCoord;  // 0: TEXCOORD_0, 1: TEXCOORD_1
  float scale;    // the normal map's scale of its x and y; a layer texture's floor (below); 1 for the others
  uint param;     // a layer texture's parameter slot (MaterialTextures.layerModel's); unused by the others
  vec3 row0;
  vec3 row1;
};
RL_CHECK_SIZE(TextureRef, 40);

// MaterialTextures.refs, one slot per use; every material with textures has a record with all of them.
RL_CONST uint kTextureBaseColor = 0;          // sRGB; multiplies the diffuse colour
RL_CONST uint kTextureMetallicRoughness = 1;  // linear; G scales roughness, B metallic
RL_CONST uint kTextureNormal = 2;             // linear; tangent-space normal, 2 c - 1
RL_CONST uint kTextureEmissive = 3;           // sRGB; multiplies the emitted radiance
RL_CONST uint kTextureSpecular = 4;           // linear; A scales the specular_weight role (KHR_materials_specular)
RL_CONST uint kTextureSpecularColor = 5;      // sRGB; RGB scales the specular_tint role (KHR_materials_specular)
// The layer textures of glTF's layered extensions, each scaling one parameter of the model they were read for
// (openpbr): the parameter at slot `param` becomes param x (scale + (1 - scale) texel), scale being 0 but for the
// film's thickness, which runs from iridescenceThicknessMinimum (scale = minimum / maximum) to the maximum.
RL_CONST uint kTextureCoat = 6;                 // linear; R scales the coat's weight (clearcoatTexture, coatTexture)
RL_CONST uint kTextureCoatRoughness = 7;        // linear; G its roughness (clearcoatRoughnessTexture, coatRoughness...)
RL_CONST uint kTextureSheenColor = 8;           // sRGB; RGB the fuzz's colour (sheenColorTexture, fuzzColorTexture)
RL_CONST uint kTextureSheenRoughness = 9;       // linear; A the fuzz's roughness (sheenRoughness..., fuzzRoughness...)
RL_CONST uint kTextureIridescence = 10;         // linear; R the thin film's weight (iridescenceTexture)
RL_CONST uint kTextureIridescenceThickness = 11;  // linear; G the film's thickness (iridescenceThicknessTexture)
RL_CONST uint kTextureTransmission = 12;        // linear; R the transmission weight (transmissionTexture)
RL_CONST uint kTextureCoatColor = 13;           // sRGB; RGB the coat's colour (coatColorTexture)
RL_CONST uint kTextureFuzz = 14;                // linear; R the fuzz's weight (fuzzTexture)
RL_CONST uint kTextureDiffuseRoughness = 15;    // linear; R the diffuse roughness (diffuseRoughnessTexture)
RL_CONST uint kTextureDiffuseTransmission = 16;       // linear; A the subsurface weight (diffuseTransmissionTexture)
RL_CONST uint kTextureDiffuseTransmissionColor = 17;  // sRGB; RGB its colour (diffuseTransmissionColorTexture)
RL_CONST uint kFirstLayerTexture = 6;
RL_CONST uint kLayerTexturesEnd = 18;  // the layer textures are the uses kFirstLayerTexture .. kLayerTexturesEnd - 1
// KHR_materials_anisotropy's texture: linear; RG the direction in the tangent plane (2 c - 1, from the tangent
// towards the bitangent), B scales the strength, which `scale` holds; `param` is the anisotropy's slot. The strength
// reaches it through glTF's map onto openpbr's ratio (gltf_materials.cpp, anisotropyOf), the roughness role's value.
RL_CONST uint kTextureAnisotropy = 18;
// The coat's own normal map (its param: the slot of geometry_coat_normal_x, y after it), of layerModel.
RL_CONST uint kTextureCoatNormal = 19;
// KHR_materials_coat's coatAnisotropyTexture, read as the base's anisotropy texture: RG the direction, B scales the
// strength (`scale`, the factor). `param` packs three slots of layerModel, 8 bits each: the coat's anisotropy (bits
// 0-7), its roughness (8-15) and geometry_coat_tangent_angle (16-23); 0: none. The coat's angle from the shading
// frame's tangent gains the texel's turn and loses the base anisotropy texel's, which that tangent already carries:
// a coat whose base turns texel by texel has this use without a texture (texture -1, param set) for that alone.
RL_CONST uint kTextureCoatAnisotropy = 20;
RL_CONST uint kTextureUses = 21;

// MaterialTextures.alphaMode (glTF alphaMode). Opaque surfaces are opaque geometry: traversal never asks.
RL_CONST uint kAlphaOpaque = 0;
RL_CONST uint kAlphaMask = 1;   // a hit counts where alpha >= alphaCutoff: holes elsewhere
RL_CONST uint kAlphaBlend = 2;  // a hit counts with probability alpha (stochastic transparency)

struct MaterialTextures {
  TextureRef refs[kTextureUses];
  uint alphaMode;
  float alpha;        // baseColorFactor's alpha; the base-colour texture's alpha multiplies it
  float alphaCutoff;  // kAlphaMask only
  uint layerModel;    // the model whose slots the layer textures name (kNoParam: none); they apply to it only (a
                      // material switched to another model in the viewer reads them again when switched back)
  // Radians the anisotropy's direction turns from the tangent towards the bitangent (KHR_materials_anisotropy's
  // anisotropyRotation), with the layer textures (layerModel's only).
  float anisotropyRotation;
};
RL_CHECK_SIZE(MaterialTextures, 860);

// One light for next event estimation, of any kind (generated/light_kinds.h, from shaders/lights/lights.cmake):
// punctual lights, emitting triangles and spheres in world space, the environment. What p0, p1, p2 and radiance
// hold is each kind's (its file in shaders/lights/ says). Lights are picked in proportion to their power by the
// inclusive `cdf` (the light-selection distribution, engine/render/light_records.cpp); `pmf` is this one's.
struct LightRecord {
  vec3 p0;
  uint kind;
  vec3 p1;
  float pmf;
  vec3 p2;
  float cdf;
  vec3 radiance;  // L_e, or a punctual light's intensity (W/sr) or irradiance (W/m^2)
  float area;     // emitting surfaces: their area
  // An emitting triangle whose material has an emissive texture: its InstanceRecord and primitive, whose UVs
  // and material give L_e at each point (radiance is then the factor the texture multiplies); else kNoInstance.
  uint texturedInstance;
  uint primitive;
};
RL_CHECK_SIZE(LightRecord, 72);

RL_NAMESPACE_END

#endif
