// Scene data as the kernels see it: instances, geometry, materials and lights.
#ifndef RAYLAB_SHARED_SCENE_RECORDS_H
#define RAYLAB_SHARED_SCENE_RECORDS_H

#include "compat.h"

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
  uint firstEmitter;  // EmitterRecord of primitive 0 when the instance emits, else kNoEmitter
};
RL_CHECK_SIZE(InstanceRecord, 28);

RL_CONST uint kNoEmitter = 0xFFFFFFFFu;

// EmitterRecord.kind
RL_CONST uint kEmitterTriangle = 0;
RL_CONST uint kEmitterSphere = 1;

// One emitting primitive in world space, for next event estimation: emitters are picked in proportion to
// their power (luminance of L_e times area) by the inclusive `cdf`; `pmf` is the probability of this one.
struct EmitterRecord {
  vec3 p0;        // triangle: first vertex (counter-clockwise front); sphere: centre
  uint kind;
  vec3 p1;        // triangle: second vertex; sphere: (radius, 0, 0)
  float pmf;
  vec3 p2;        // triangle: third vertex
  float cdf;
  vec3 radiance;  // L_e
  float area;
};
RL_CHECK_SIZE(EmitterRecord, 64);

// The environment image (binding kBindingEnvironment): this header, then `data`, floats in four arrays of the
// image's texels, rows from the top: linear RGB (3 per texel), then the sampling density f (luminance times
// sin(theta), 1 per texel), its inclusive cdf along each row normalised to 1 per row (1 per texel), and the
// inclusive cdf over rows (1 per row). Directions have pdf f / fMean / (2 pi^2 sin theta) per unit solid angle
// (docs/integrators.md, "Environment light").
struct EnvironmentHeader {
  uint width;   // 0: no image (the scene's uniform background)
  uint height;
  float fMean;  // mean of f over the texels; 0: nothing to sample
  uint reserved;
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

// LightRecord.type
RL_CONST uint kLightPoint = 0;
RL_CONST uint kLightSpot = 1;
RL_CONST uint kLightDirectional = 2;
// A point light carried with the camera: `position` is its offset along the camera's right, up and forward axes
// (world units), so it lights whatever the camera sees. Files without lights get one (docs/scenes.md).
RL_CONST uint kLightHeadlight = 3;

struct LightRecord {
  vec3 position;
  uint type;
  vec3 intensity;   // RGB radiant intensity in W/sr (point, spot) or irradiance in W/m^2 (directional)
  float cosInner;   // spot: full intensity inside this cone
  vec3 direction;   // spot, directional: the direction light travels, unit length
  float cosOuter;   // spot: no light outside this cone
};
RL_CHECK_SIZE(LightRecord, 48);

RL_NAMESPACE_END

#endif
