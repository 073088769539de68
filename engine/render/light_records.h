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

// SceneLights.materials of a record that is not an emitting surface (a punctual light, the environment).
inline constexpr std::uint32_t kNoEmitterMaterial = 0xFFFFFFFFu;

struct SceneLights {
  // Punctual lights first, in scene.lights order (the slides' integrator sums exactly these), then each emitting
  // mesh instance's triangles, the spheres, the environment.
  std::vector<gpu::LightRecord> records;
  std::vector<double> powers;  // per record, in watts of luminance: the distribution over non-delta lights
  // Per record, for live edits of emission (updateEmitters): the material of an emitting triangle or sphere
  // (gpu::kNoMaterial for the others), and the mean of its emissive texture over its surface (1 without one).
  std::vector<std::uint32_t> materials;
  std::vector<glm::dvec3> texelMeans;
  // Materials of traced geometry that have no records (they did not emit at upload): one that emits later needs
  // the records made anew (updateEmitters says so).
  std::vector<std::uint32_t> materialsWithoutRecords;
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

// Live edits of materials (the viewer, sweeps): each emitter's radiance (emission times opacity) and power from
// `materials`, and the selection distribution again. False when a material without records now emits: its
// geometry has no records to sample, and the scene must be uploaded again for next event estimation to see it.
bool updateEmitters(SceneLights& sceneLights, std::span<const Material> materials);

}  // namespace raylab
