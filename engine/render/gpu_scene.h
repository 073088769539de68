// A scene on the device: geometry, material and light buffers, the BLASes and the TLAS, and the descriptor
// bindings every kernel uses to read them (shaders/shared/bindings.h).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "brdf_tables/brdf_tables.h"
#include "render/light_records.h"
#include "scene/scene.h"
#include "vk/accel.h"
#include "vk/device.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace raylab {

struct GpuScene {
  Buffer instances;
  Buffer positions;
  Buffer normals;
  Buffer uvs;
  Buffer uvs1;      // TEXCOORD_1, when a material reads it
  Buffer tangents;  // vec4 per vertex, when a material has a normal map
  Buffer indices;
  Buffer spheres;
  Buffer sphereAabbs;
  Buffer materials;
  Buffer lights;    // LightRecord[]: every light, with the light-selection distribution (light_records.h)
  Buffer textures;  // TextureRecord[]
  Buffer texels;    // RGBA8 texels of every texture
  Buffer materialTextures;  // MaterialTextures[]
  Buffer environment;  // EnvironmentHeader, the environment image and its sampling tables
  Buffer brdfTables;   // the BRDF library's tables (brdf_tables/brdf_tables.h)
  std::vector<std::uint32_t> measuredFiles;  // the measured files in brdfTables, in block order
  std::vector<AccelerationStructure> blases;
  AccelerationStructure tlas;
  // gpu::kGeometry... of each TLAS instance, in instance order: instance i's custom index and SBT record
  // offset are both i, and a ray-tracing pipeline's hit record i must be of this geometry's hit group.
  std::vector<std::uint32_t> instanceGeometry;
  // The upload orders primitives and instances spatially (scene/spatial_order.h); per instance record, the id it
  // has in the scene's own order, and the scene's index of each of its primitives: what the ray probe reports.
  std::vector<std::uint32_t> sceneRecord;
  std::vector<std::shared_ptr<const std::vector<std::uint32_t>>> scenePrimitive;
  SceneLights sceneLights;  // the host's copy of `lights`, which live edits of the punctual lights rewrite
  std::uint32_t lightCount = 0;          // LightRecords
  std::uint32_t punctualLightCount = 0;  // the scene's punctual lights, the first LightRecords
  std::uint32_t materialCount = 0;
  std::uint64_t triangleCount = 0;
  std::uint32_t sphereCount = 0;
  double accelerationBuildSeconds = 0.0;  // BLAS + TLAS builds, uploads of their inputs included
};

struct SceneUpload {
  // False submits the primitives in the scene's own order (only `raylab bench rays --submitted-order` does, to
  // measure what the order is worth).
  bool spatialOrder = true;
  // The viewer's: any material may become partly transparent by a later edit (a model switched to openpbr, its
  // geometry_opacity lowered), so every mesh is non-opaque geometry. That costs nothing while no material is
  // transparent: the kernel without the alpha feature traces with the opaque ray flag.
  bool materialsEditable = false;
};

GpuScene uploadScene(const Device& device, const Scene& scene, const SceneUpload& upload = {});
// The materials' records as the device sees them, and the measured files they use (brdf_tables/brdf_tables.h).
DeviceMaterials deviceMaterialsOf(std::span<const Material> materials);
void destroyGpuScene(const Device& device, GpuScene& gpuScene);

// Live edits (the viewer, sweeps): same counts as uploaded, new values. updateMaterials also updates the emitters'
// light records (their radiance and the selection by power).
struct MaterialUpdate {
  // The materials now use other measured files: brdfTables was replaced, and every descriptor set holding the old
  // one must be written again (writeSceneDescriptors).
  bool tablesReplaced = false;
  // False when a material whose geometry had no light records now emits (updateEmitters): next event estimation
  // cannot see it until the scene is uploaded again.
  bool emittersComplete = true;
};
MaterialUpdate updateMaterials(const Device& device, GpuScene& gpuScene, std::span<const Material> materials);
void updateLights(const Device& device, GpuScene& gpuScene, std::span<const Light> lights);

// The scene's descriptor bindings, to merge into a kernel's set layout, and writing them into a set.
std::vector<DescriptorBinding> sceneBindings();
void writeSceneDescriptors(const Device& device, VkDescriptorSet set, const GpuScene& gpuScene);

}  // namespace raylab
