#include "render/gpu_scene.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "brdf_params/material_params.h"
#include "brdf_tables/brdf_tables.h"
#include "scene/environment_tables.h"
#include "scene/spatial_order.h"
#include "shared/bindings.h"
#include "util/error.h"
#include "util/timer.h"

namespace raylab {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

void copyTransform(const glm::mat4& m, float out[3][4]) {
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) out[row][column] = m[column][row];  // glm is column-major
  }
}

// Concatenated vertex and index arrays of every mesh; per-mesh offsets say where each starts.
struct PackedMeshes {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec2> uvs1;      // only when some mesh has TEXCOORD_1 for its textures
  std::vector<glm::vec4> tangents;  // only when some mesh has a normal map
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> firstVertex;
  std::vector<std::uint32_t> firstIndex;
  std::vector<std::uint32_t> vertexFlags;
};

// A mesh's per-vertex attribute after the previous meshes', or zeros up to `vertexTotal` without one.
template <typename T>
void appendAttribute(std::vector<T>& packed, const std::vector<T>& attribute, std::size_t vertexTotal) {
  if (attribute.empty()) packed.resize(vertexTotal, T(0.0f));
  else packed.insert(packed.end(), attribute.begin(), attribute.end());
}

PackedMeshes packMeshes(const Scene& scene) {
  PackedMeshes packed;
  const bool anyUvs1 = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.uvs1.empty(); });
  const bool anyTangents =
      std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.tangents.empty(); });
  for (const Mesh& mesh : scene.meshes) {
    const std::size_t vertexCount = mesh.positions.size();
    const auto checkCount = [&](std::size_t count, const char* what) {
      if (count != 0 && count != vertexCount) {
        throw Error("mesh '" + mesh.name + "': " + std::to_string(count) + " " + what + " for " +
                    std::to_string(vertexCount) + " positions");
      }
    };
    checkCount(mesh.normals.size(), "normals");
    checkCount(mesh.uvs.size(), "UVs");
    checkCount(mesh.uvs1.size(), "TEXCOORD_1 UVs");
    checkCount(mesh.tangents.size(), "tangents");
    if (mesh.indices.size() % 3 != 0) throw Error("mesh '" + mesh.name + "': index count is not a multiple of 3");
    for (std::uint32_t index : mesh.indices) {
      if (index >= vertexCount) {
        throw Error("mesh '" + mesh.name + "': index " + std::to_string(index) + " is out of range (" +
                    std::to_string(vertexCount) + " vertices)");
      }
    }
    packed.firstVertex.push_back(static_cast<std::uint32_t>(packed.positions.size()));
    packed.firstIndex.push_back(static_cast<std::uint32_t>(packed.indices.size()));
    std::uint32_t flags = 0;
    if (!mesh.normals.empty()) flags |= gpu::kVertexHasNormals;
    if (!mesh.uvs.empty()) flags |= gpu::kVertexHasUvs;
    if (!mesh.uvs1.empty()) flags |= gpu::kVertexHasUvs1;
    if (!mesh.tangents.empty()) flags |= gpu::kVertexHasTangents;
    packed.vertexFlags.push_back(flags);
    packed.positions.insert(packed.positions.end(), mesh.positions.begin(), mesh.positions.end());
    // Absent attributes still get slots, so one index addresses every array; TEXCOORD_1 and tangents only exist
    // when some mesh has them.
    appendAttribute(packed.normals, mesh.normals, packed.positions.size());
    appendAttribute(packed.uvs, mesh.uvs, packed.positions.size());
    if (anyUvs1) appendAttribute(packed.uvs1, mesh.uvs1, packed.positions.size());
    if (anyTangents) appendAttribute(packed.tangents, mesh.tangents, packed.positions.size());
    packed.indices.insert(packed.indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  return packed;
}

// Every texture's texels one after another, as packed RGBA8 words (RGBA16: two words a texel), and the record
// saying where each starts.
void packTextures(const Scene& scene, std::vector<gpu::TextureRecord>& records, std::vector<std::uint32_t>& texels) {
  for (const Texture& texture : scene.textures) {
    const std::size_t count = std::size_t(texture.width) * texture.height;
    const bool sixteen = !texture.rgba16.empty();
    const std::size_t values = sixteen ? texture.rgba16.size() : texture.rgba.size();
    if (count == 0 || values != count * 4) {
      throw Error("texture '" + texture.name + "': " + std::to_string(values) + " channel values for " +
                  std::to_string(texture.width) + "x" + std::to_string(texture.height) + " RGBA texels");
    }
    records.push_back({static_cast<std::uint32_t>(texels.size()), texture.width, texture.height,
                       texture.wrapS | (texture.wrapT << 2) | (texture.nearest ? gpu::kFilterNearest : 0u) |
                           (sixteen ? gpu::kTexels16 : 0u)});
    for (std::size_t i = 0; i < count; ++i) {
      if (sixteen) {
        const std::uint16_t* t = &texture.rgba16[i * 4];
        texels.push_back(std::uint32_t(t[0]) | std::uint32_t(t[1]) << 16);
        texels.push_back(std::uint32_t(t[2]) | std::uint32_t(t[3]) << 16);
      } else {
        const std::uint8_t* t = &texture.rgba[i * 4];
        texels.push_back(std::uint32_t(t[0]) | std::uint32_t(t[1]) << 8 | std::uint32_t(t[2]) << 16 |
                         std::uint32_t(t[3]) << 24);
      }
    }
  }
}

std::string mebibytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
  return text;
}

// Every buffer a kernel binds must fit the device's maxStorageBufferRange, and every BLAS and the TLAS its
// acceleration-structure limits (lavapipe accepts more, but that is outside Vulkan's rules and fails on GPUs).
// Checked before anything is created, so that a refusal leaves nothing behind.
void checkDeviceLimits(const Device& device, const Scene& scene) {
  const std::uint64_t maxRange = device.properties.limits.maxStorageBufferRange;
  const auto checkBuffer = [&](const std::string& what, std::uint64_t bytes) {
    if (bytes > maxRange) {
      throw Error("the scene's " + what + " need " + mebibytes(bytes) + ", over this device's maxStorageBufferRange of " +
                  mebibytes(maxRange) + ": simplify the scene or split it (docs/scenes.md, Limits)");
    }
  };
  std::uint64_t vertices = 0, indices = 0, texels = 0;
  for (const Mesh& mesh : scene.meshes) {
    vertices += mesh.positions.size();
    indices += mesh.indices.size();
    if (mesh.indices.size() / 3 > device.maxPrimitiveCount) {
      throw Error("mesh '" + mesh.name + "' has " + std::to_string(mesh.indices.size() / 3) +
                  " triangles, over this device's maxPrimitiveCount of " + std::to_string(device.maxPrimitiveCount) +
                  ": split the mesh into several primitives");
    }
  }
  // Texel words: one per RGBA8 texel, two per RGBA16 one.
  for (const Texture& texture : scene.textures) {
    texels += std::uint64_t(texture.width) * texture.height * (texture.rgba16.empty() ? 1 : 2);
  }
  checkBuffer("vertex positions (" + std::to_string(vertices) + ")", vertices * sizeof(glm::vec3));
  checkBuffer("triangle indices (" + std::to_string(indices) + ")", indices * sizeof(std::uint32_t));
  checkBuffer("texture texels (" + std::to_string(texels) + " words)", texels * sizeof(std::uint32_t));
  checkBuffer("spheres (" + std::to_string(scene.spheres.size()) + ")",
              scene.spheres.size() * sizeof(gpu::SphereRecord));
  std::uint64_t emitting = scene.lights.size() + scene.spheres.size() + 1;
  for (const MeshInstance& instance : scene.instances) {
    if (emits(scene, instance.material)) emitting += scene.meshes[instance.mesh].indices.size() / 3;
  }
  checkBuffer("lights and emitting primitives (" + std::to_string(emitting) + ")", emitting * sizeof(gpu::LightRecord));
  checkBuffer("environment image (" + std::to_string(scene.environment.width) + "x" +
                  std::to_string(scene.environment.height) + ") and its sampling tables",
              environmentBufferBytes(scene.environment.width, scene.environment.height));
  if (scene.spheres.size() > device.maxPrimitiveCount) {
    throw Error("the scene has " + std::to_string(scene.spheres.size()) +
                " spheres, over this device's maxPrimitiveCount of " + std::to_string(device.maxPrimitiveCount));
  }
  if (scene.instances.size() + 1 > device.maxInstanceCount) {
    throw Error("the scene has " + std::to_string(scene.instances.size()) +
                " mesh instances, over this device's maxInstanceCount of " + std::to_string(device.maxInstanceCount));
  }
}

}  // namespace

namespace {
void fillGpuScene(const Device& device, const Scene& scene, const SceneUpload& upload, GpuScene& gpuScene);
}  // namespace

GpuScene uploadScene(const Device& device, const Scene& scene, const SceneUpload& upload) {
  checkDeviceLimits(device, scene);
  for (const MeshInstance& instance : scene.instances) {
    if (instance.mesh >= scene.meshes.size()) throw Error("an instance refers to a mesh that does not exist");
    if (instance.material >= scene.materials.size()) throw Error("an instance refers to a material that does not exist");
  }
  for (const Sphere& sphere : scene.spheres) {
    if (sphere.material >= scene.materials.size()) throw Error("a sphere refers to a material that does not exist");
  }
  for (const Material& material : scene.materials) {
    const int textures = material.record.textures;
    if (textures >= 0 && static_cast<std::size_t>(textures) >= scene.materialTextures.size()) {
      throw Error("material '" + material.name + "' refers to texture set " + std::to_string(textures) +
                  ", which does not exist");
    }
  }
  for (const gpu::MaterialTextures& uses : scene.materialTextures) {
    for (const gpu::TextureRef& ref : uses.refs) {
      if (ref.texture >= 0 && static_cast<std::size_t>(ref.texture) >= scene.textures.size()) {
        throw Error("a material refers to texture " + std::to_string(ref.texture) + ", which does not exist");
      }
      if (ref.texCoord > 1) throw Error("a material reads TEXCOORD_" + std::to_string(ref.texCoord) + " (0 or 1)");
    }
  }

  // The GpuScene owns what is created into it: a failure at any step releases everything made before it.
  GpuScene gpuScene;
  try {
    fillGpuScene(device, scene, upload, gpuScene);
  } catch (...) {
    destroyGpuScene(device, gpuScene);
    throw;
  }
  return gpuScene;
}

namespace {

// The ids the probe reports, as they would be without the spatial order: an instance record's index in the scene's
// order of instances (those with triangles, then the spheres' record), a primitive's index in its mesh or among
// the spheres.
void recordSceneIds(const Scene& original, const OrderedGeometry& geometry, GpuScene& gpuScene) {
  std::vector<std::uint32_t> recordOfInstance(original.instances.size(), UINT32_MAX);
  std::uint32_t records = 0;
  for (std::size_t i = 0; i < original.instances.size(); ++i) {
    if (!original.meshes[original.instances[i].mesh].indices.empty()) recordOfInstance[i] = records++;
  }
  std::vector<std::shared_ptr<const std::vector<std::uint32_t>>> meshOrders;
  for (const std::vector<std::uint32_t>& order : geometry.triangles) {
    meshOrders.push_back(std::make_shared<const std::vector<std::uint32_t>>(order));
  }
  for (std::uint32_t i : geometry.instances) {
    if (recordOfInstance[i] == UINT32_MAX) continue;
    gpuScene.sceneRecord.push_back(recordOfInstance[i]);
    gpuScene.scenePrimitive.push_back(meshOrders[original.instances[i].mesh]);
  }
  if (!original.spheres.empty()) {
    gpuScene.sceneRecord.push_back(records);
    gpuScene.scenePrimitive.push_back(std::make_shared<const std::vector<std::uint32_t>>(geometry.spheres));
  }
}

void fillGpuScene(const Device& device, const Scene& original, const SceneUpload& upload, GpuScene& gpuScene) {
  const Stopwatch clock;
  // Geometry, light records and primitive ids come from the primitives in spatial order (lavapipe's builder splits
  // at the midpoint of the submitted order); the images from the scene itself.
  const OrderedGeometry geometry = spatiallyOrderedGeometry(original, upload.spatialOrder);
  const Scene& scene = geometry.scene;
  const PackedMeshes packed = packMeshes(scene);
  gpuScene.positions = createBufferWithData<glm::vec3>(device, packed.positions, kStorage | kAsInputUsage,
                                                       "positions");
  gpuScene.normals = createBufferWithData<glm::vec3>(device, packed.normals, kStorage, "normals");
  gpuScene.uvs = createBufferWithData<glm::vec2>(device, packed.uvs, kStorage, "uvs");
  gpuScene.uvs1 = createBufferWithData<glm::vec2>(device, packed.uvs1, kStorage, "uvs1");
  gpuScene.tangents = createBufferWithData<glm::vec4>(device, packed.tangents, kStorage, "tangents");
  gpuScene.indices = createBufferWithData<std::uint32_t>(device, packed.indices, kStorage | kAsInputUsage,
                                                         "indices");

  std::vector<gpu::SphereRecord> sphereRecords;
  std::vector<VkAabbPositionsKHR> aabbs;
  for (const Sphere& sphere : scene.spheres) {
    if (!(sphere.radius > 0.0f)) throw Error("a sphere has radius " + std::to_string(sphere.radius) + "; it must be > 0");
    sphereRecords.push_back({sphere.center, sphere.radius, sphere.material});
    const glm::vec3 low = sphere.center - sphere.radius;
    const glm::vec3 high = sphere.center + sphere.radius;
    aabbs.push_back({low.x, low.y, low.z, high.x, high.y, high.z});
  }
  gpuScene.spheres = createBufferWithData<gpu::SphereRecord>(device, sphereRecords, kStorage, "spheres");
  gpuScene.sphereAabbs = createBufferWithData<VkAabbPositionsKHR>(device, aabbs, kAsInputUsage, "sphere AABBs");
  gpuScene.sphereCount = static_cast<std::uint32_t>(sphereRecords.size());

  // One BLAS per mesh, plus one BLAS holding every sphere.
  std::vector<BlasInput> blasInputs;
  std::vector<std::uint32_t> meshBlas(scene.meshes.size(), UINT32_MAX);
  // A mesh any of whose instances is alpha-tested or blended, or may be partly transparent (a model with an opacity,
  // or any material of an editable scene), is non-opaque geometry.
  std::vector<bool> meshOpaque(scene.meshes.size(), true);
  for (const MeshInstance& instance : scene.instances) {
    const gpu::MaterialRecord& record = scene.materials[instance.material].record;
    if (upload.materialsEditable || hasAlpha(original, record) || hasOpacity(modelInfo(record.model))) {
      meshOpaque[instance.mesh] = false;
    }
  }
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    if (mesh.indices.empty()) continue;
    BlasInput input;
    input.kind = BlasInput::Kind::kTriangles;
    input.vertices = gpuScene.positions.address + packed.firstVertex[i] * sizeof(glm::vec3);
    input.vertexCount = static_cast<std::uint32_t>(mesh.positions.size());
    input.indices = gpuScene.indices.address + packed.firstIndex[i] * sizeof(std::uint32_t);
    input.triangleCount = static_cast<std::uint32_t>(mesh.indices.size() / 3);
    input.opaque = meshOpaque[i];
    meshBlas[i] = static_cast<std::uint32_t>(blasInputs.size());
    blasInputs.push_back(input);
  }
  std::uint32_t sphereBlas = UINT32_MAX;
  if (!aabbs.empty()) {
    BlasInput input;
    input.kind = BlasInput::Kind::kAabbs;
    input.aabbs = gpuScene.sphereAabbs.address;
    input.aabbCount = static_cast<std::uint32_t>(aabbs.size());
    sphereBlas = static_cast<std::uint32_t>(blasInputs.size());
    blasInputs.push_back(input);
  }
  gpuScene.blases = buildBlases(device, blasInputs);

  std::vector<gpu::InstanceRecord> instanceRecords;
  std::vector<TlasInstance> tlasInstances;
  const EnvironmentTables environmentTables = buildEnvironmentTables(original.environment);
  // Instance records in the order the loop below appends them: traced mesh instances, then the spheres' record.
  EmitterSurfaces emitterSurfaces;
  emitterSurfaces.textures = original.textures;
  std::uint32_t tracedInstances = 0;
  for (const MeshInstance& instance : scene.instances) {
    emitterSurfaces.instanceRecords.push_back(meshBlas[instance.mesh] == UINT32_MAX ? gpu::kNoInstance
                                                                                    : tracedInstances++);
  }
  if (sphereBlas != UINT32_MAX) emitterSurfaces.sphereInstanceRecord = tracedInstances;
  gpuScene.sceneLights = sceneLights(scene, environmentTables, emitterSurfaces);
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& instance = scene.instances[i];
    if (meshBlas[instance.mesh] == UINT32_MAX) continue;
    gpu::InstanceRecord record{};
    record.firstLight = gpuScene.sceneLights.instanceFirstLight[i];
    record.geometryKind = gpu::kGeometryTriangles;
    record.material = instance.material;
    record.firstIndex = packed.firstIndex[instance.mesh];
    record.firstVertex = packed.firstVertex[instance.mesh];
    record.vertexFlags = packed.vertexFlags[instance.mesh];
    TlasInstance tlasInstance;
    tlasInstance.blas = meshBlas[instance.mesh];
    copyTransform(instance.transform, tlasInstance.transform);
    tlasInstance.customIndex = static_cast<std::uint32_t>(instanceRecords.size());
    tlasInstance.sbtRecord = tlasInstance.customIndex;
    tlasInstances.push_back(tlasInstance);
    instanceRecords.push_back(record);
    gpuScene.triangleCount += scene.meshes[instance.mesh].indices.size() / 3;
  }
  if (sphereBlas != UINT32_MAX) {
    gpu::InstanceRecord record{};
    record.geometryKind = gpu::kGeometrySpheres;
    record.firstSphere = 0;
    record.firstLight = gpuScene.sceneLights.sphereFirstLight;
    TlasInstance tlasInstance;
    tlasInstance.blas = sphereBlas;
    copyTransform(glm::mat4(1.0f), tlasInstance.transform);
    tlasInstance.customIndex = static_cast<std::uint32_t>(instanceRecords.size());
    tlasInstance.sbtRecord = tlasInstance.customIndex;
    tlasInstances.push_back(tlasInstance);
    instanceRecords.push_back(record);
  }
  for (const gpu::InstanceRecord& record : instanceRecords) gpuScene.instanceGeometry.push_back(record.geometryKind);
  recordSceneIds(original, geometry, gpuScene);
  gpuScene.tlas = buildTlas(device, gpuScene.blases, tlasInstances);
  gpuScene.accelerationBuildSeconds = clock.seconds();

  gpuScene.instances = createBufferWithData<gpu::InstanceRecord>(device, instanceRecords, kStorage, "instances");
  const DeviceMaterials materials = deviceMaterialsOf(scene.materials);
  gpuScene.materials = createBufferWithData<gpu::MaterialRecord>(device, materials.records, kStorage, "materials");
  gpuScene.materialCount = static_cast<std::uint32_t>(materials.records.size());
  gpuScene.measuredFiles = materials.measuredFiles;
  const SceneLights& lights = gpuScene.sceneLights;
  // A buffer may not be empty: a scene without lights gets one black record that nothing counts.
  const std::vector<gpu::LightRecord> lightRecords =
      lights.records.empty() ? std::vector<gpu::LightRecord>(1) : lights.records;
  gpuScene.lights = createBufferWithData<gpu::LightRecord>(device, lightRecords, kStorage, "lights");
  gpuScene.lightCount = static_cast<std::uint32_t>(lights.records.size());
  gpuScene.punctualLightCount = lights.punctualCount;

  std::vector<gpu::TextureRecord> textureRecords;
  std::vector<std::uint32_t> texels;
  packTextures(original, textureRecords, texels);
  gpuScene.textures = createBufferWithData<gpu::TextureRecord>(device, textureRecords, kStorage, "textures");
  gpuScene.texels = createBufferWithData<std::uint32_t>(device, texels, kStorage, "texels");
  gpuScene.materialTextures = createBufferWithData<gpu::MaterialTextures>(device, original.materialTextures, kStorage,
                                                                          "material textures");
  const std::vector<float> environment = packEnvironment(original.environment, environmentTables, lights.environmentLight);
  gpuScene.environment = createBufferWithData<float>(device, environment, kStorage, "environment");
  gpuScene.brdfTables = createBrdfTables(device, gpuScene.measuredFiles);
}

}  // namespace

DeviceMaterials deviceMaterialsOf(std::span<const Material> materials) {
  std::vector<gpu::MaterialRecord> records;
  std::vector<std::string> names;
  for (const Material& material : materials) {
    records.push_back(material.record);
    names.push_back(material.name);
  }
  return deviceMaterials(records, names);
}

void destroyGpuScene(const Device& device, GpuScene& gpuScene) {
  destroyAccelerationStructure(device, gpuScene.tlas);
  for (AccelerationStructure& blas : gpuScene.blases) destroyAccelerationStructure(device, blas);
  for (Buffer* buffer : {&gpuScene.instances, &gpuScene.positions, &gpuScene.normals, &gpuScene.uvs,
                         &gpuScene.indices, &gpuScene.spheres, &gpuScene.sphereAabbs, &gpuScene.materials,
                         &gpuScene.lights, &gpuScene.textures, &gpuScene.texels, &gpuScene.environment,
                         &gpuScene.brdfTables, &gpuScene.uvs1, &gpuScene.tangents, &gpuScene.materialTextures}) {
    destroyBuffer(device, *buffer);
  }
  gpuScene = {};
}

MaterialUpdate updateMaterials(const Device& device, GpuScene& gpuScene, std::span<const Material> materials) {
  if (materials.size() != gpuScene.materialCount) throw Error("updateMaterials: the material count changed");
  const DeviceMaterials records = deviceMaterialsOf(materials);
  MaterialUpdate update;
  update.tablesReplaced = updateBrdfTables(device, gpuScene.brdfTables, gpuScene.measuredFiles, records.measuredFiles);
  uploadBuffer<gpu::MaterialRecord>(device, gpuScene.materials, records.records);
  update.emittersComplete = updateEmitters(gpuScene.sceneLights, materials);
  if (!gpuScene.sceneLights.records.empty()) {
    uploadBuffer<gpu::LightRecord>(device, gpuScene.lights, gpuScene.sceneLights.records);
  }
  return update;
}

void updateLights(const Device& device, GpuScene& gpuScene, std::span<const Light> lights) {
  updatePunctualLights(gpuScene.sceneLights, lights);
  if (!gpuScene.sceneLights.records.empty()) {
    uploadBuffer<gpu::LightRecord>(device, gpuScene.lights, gpuScene.sceneLights.records);
  }
}

std::vector<DescriptorBinding> sceneBindings() {
  return {
      {gpu::kBindingTlas, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR},
      {gpu::kBindingInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingUvs, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingIndices, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingSpheres, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingMaterials, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingTextures, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingTexels, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingMaterialTextures, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingUvs1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingTangents, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingEnvironment, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {gpu::kBindingBrdfTables, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
  };
}

void writeSceneDescriptors(const Device& device, VkDescriptorSet set, const GpuScene& gpuScene) {
  writeAccelerationStructure(device, set, gpu::kBindingTlas, gpuScene.tlas.handle);
  writeStorageBuffer(device, set, gpu::kBindingInstances, gpuScene.instances.handle);
  writeStorageBuffer(device, set, gpu::kBindingPositions, gpuScene.positions.handle);
  writeStorageBuffer(device, set, gpu::kBindingNormals, gpuScene.normals.handle);
  writeStorageBuffer(device, set, gpu::kBindingUvs, gpuScene.uvs.handle);
  writeStorageBuffer(device, set, gpu::kBindingIndices, gpuScene.indices.handle);
  writeStorageBuffer(device, set, gpu::kBindingSpheres, gpuScene.spheres.handle);
  writeStorageBuffer(device, set, gpu::kBindingMaterials, gpuScene.materials.handle);
  writeStorageBuffer(device, set, gpu::kBindingLights, gpuScene.lights.handle);
  writeStorageBuffer(device, set, gpu::kBindingTextures, gpuScene.textures.handle);
  writeStorageBuffer(device, set, gpu::kBindingTexels, gpuScene.texels.handle);
  writeStorageBuffer(device, set, gpu::kBindingMaterialTextures, gpuScene.materialTextures.handle);
  writeStorageBuffer(device, set, gpu::kBindingUvs1, gpuScene.uvs1.handle);
  writeStorageBuffer(device, set, gpu::kBindingTangents, gpuScene.tangents.handle);
  writeStorageBuffer(device, set, gpu::kBindingEnvironment, gpuScene.environment.handle);
  writeStorageBuffer(device, set, gpu::kBindingBrdfTables, gpuScene.brdfTables.handle);
}

}  // namespace raylab
