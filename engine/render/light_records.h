// Every light of a scene as next event estimation sees it (kernel/light_sampling.glsl): one gpu::LightRecord per
// punctual light, emitting triangle, sphere and the environment image, and the light-selection distribution
// over them: every delta light with probability 1, the others one at a time in proportion to power (pbrt-v4's
// PowerLightSampler).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scene/environment_tables.h"
#include "scene/scene.h"

namespace raylab {

struct SceneLights {
  // Punctual lights first, in scene.lights order (the slides' integrator sums exactly these), then each emitting
  // mesh instance's triangles, the spheres, the environment.
  std::vector<gpu::LightRecord> records;
  std::vector<double> powers;  // per record, in watts of luminance: the distribution over non-delta lights
  std::uint32_t punctualCount = 0;
  std::vector<std::uint32_t> instanceFirstLight;  // per scene.instances: the record of its triangle 0, or kNoLight
  std::uint32_t sphereFirstLight = gpu::kNoLight;  // record of sphere i is this + i, when any sphere emits
  std::uint32_t environmentLight = gpu::kNoLight;
  float sceneRadius = 0.0f;  // of the scene's bounding sphere: the disk the environment's power crosses
};

// What the light records need besides the scene's geometry and materials: where the kernels find an emitter's
// surface (LightRecord.texturedInstance), per scene.instances its InstanceRecord (gpu::kNoInstance when it is not
// traced: an empty mesh) and the spheres' InstanceRecord; and the images emissive textures read (the upload's
// spatially ordered copy of the geometry leaves them in the original scene).
struct EmitterSurfaces {
  std::vector<std::uint32_t> instanceRecords;
  std::uint32_t sphereInstanceRecord = gpu::kNoInstance;
  std::span<const Texture> textures;
};

// An emitter with an emissive texture is chosen in proportion to its power with the texture's mean over its
// surface (the factor alone for the others), and tells the kernels its surface so that L_e is the texture's.
SceneLights sceneLights(const Scene& scene, const EnvironmentTables& environmentTables,
                        const EmitterSurfaces& surfaces);

// Bit (1 << gpu::kLight...) per kind of light `scene` has: the kinds its kernel compiles in.
std::uint32_t lightKindsOf(const Scene& scene);

// Live edits (the viewer): the punctual lights' records from `lights`.
void updatePunctualLights(SceneLights& sceneLights, std::span<const Light> lights);

}  // namespace raylab
