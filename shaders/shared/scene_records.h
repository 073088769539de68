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
RL_CONST uint kMaxMaterialParams = 16;
RL_CONST uint kNoParam = 0xFFFFFFFFu;

struct MaterialRecord {
  uint model;             // registry id: the order of shaders/brdf/models.cmake
  float delta;            // mirror-reflection weight of the direct integrator
  int baseColorTexture;   // -1: none; else multiplies the parameter at diffuseParam
  uint diffuseParam;      // slot of the model's diffuse colour (its `diffuse` role), kNoParam without one
  vec3 emission;          // emitted radiance L_e (linear RGB) from the front face; the path integrator shows it
  uint reserved;
  float params[kMaxMaterialParams];
};
RL_CHECK_SIZE(MaterialRecord, 96);

// TextureRecord.wrap: bits 0-1 for s (u), bits 2-3 for t (v), as glTF samplers define them.
RL_CONST uint kWrapRepeat = 0;
RL_CONST uint kWrapClamp = 1;
RL_CONST uint kWrapMirror = 2;

// A base-colour texture: RGBA8 texels, sRGB-encoded, rows from the top, filtered bilinearly by the kernel.
struct TextureRecord {
  uint firstTexel;  // into the texel buffer
  uint width;
  uint height;
  uint wrap;
};
RL_CHECK_SIZE(TextureRecord, 16);

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
};
RL_CHECK_SIZE(LightRecord, 64);

RL_NAMESPACE_END

#endif
