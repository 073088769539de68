#include "scene/scene.h"

#include "brdf_params/material_params.h"

namespace raylab {

gpu::MaterialRecord lambertMaterial(glm::vec3 rhoD, float delta) {
  gpu::MaterialRecord record = defaultRecord(modelId("lambert"));
  setParam(record, "rho_d", rhoD, "built-in lambert material");
  record.delta = delta;
  return record;
}

gpu::TextureRef noTextureRef() {
  gpu::TextureRef ref{};
  ref.texture = -1;
  ref.scale = 1.0f;
  ref.row0 = glm::vec3(1.0f, 0.0f, 0.0f);
  ref.row1 = glm::vec3(0.0f, 1.0f, 0.0f);
  return ref;
}

gpu::TextureRef textureRef(int texture) {
  gpu::TextureRef ref = noTextureRef();
  ref.texture = texture;
  return ref;
}

gpu::MaterialTextures noMaterialTextures() {
  gpu::MaterialTextures textures{};
  for (gpu::TextureRef& ref : textures.refs) ref = noTextureRef();
  textures.alphaMode = gpu::kAlphaOpaque;
  textures.alpha = 1.0f;
  textures.alphaCutoff = 0.5f;
  textures.layerModel = gpu::kNoParam;  // no model: no layer textures
  textures.anisotropyRotation = 0.0f;
  return textures;
}

bool hasLayerTextures(const Scene& scene, const gpu::MaterialRecord& record) {
  if (record.textures < 0 || std::size_t(record.textures) >= scene.materialTextures.size()) return false;
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(record.textures)];
  if (uses.layerModel != record.model) return false;
  for (std::uint32_t use = gpu::kFirstLayerTexture; use < gpu::kTextureUses; ++use) {
    if (uses.refs[use].texture >= 0) return true;
  }
  return uses.anisotropyRotation != 0.0f;
}

bool hasAlpha(const Scene& scene, const gpu::MaterialRecord& record) {
  if (opacityOf(record) < 1.0f) return true;
  return record.textures >= 0 && std::size_t(record.textures) < scene.materialTextures.size() &&
         scene.materialTextures[std::size_t(record.textures)].alphaMode != gpu::kAlphaOpaque;
}

PunctualLight pointLight(glm::vec3 position, glm::vec3 intensity) {
  PunctualLight light;
  light.type = gpu::kLightPoint;
  light.position = position;
  light.intensity = intensity;
  return light;
}

std::uint64_t triangleCount(const Scene& scene) {
  std::uint64_t count = 0;
  for (const MeshInstance& instance : scene.instances) count += scene.meshes[instance.mesh].indices.size() / 3;
  return count;
}

bool emits(const Scene& scene, std::uint32_t material) {
  const glm::vec3 e = scene.materials[material].record.emission;
  return e.r > 0.0f || e.g > 0.0f || e.b > 0.0f;
}

bool hasEmissiveGeometry(const Scene& scene) {
  for (const MeshInstance& instance : scene.instances) {
    if (emits(scene, instance.material)) return true;
  }
  for (const Sphere& sphere : scene.spheres) {
    if (emits(scene, sphere.material)) return true;
  }
  return false;
}

const char* lightTypeName(std::uint32_t type) {
  return type < gpu::kLightKindCount ? gpu::kLightKindNames[type] : "unknown";
}

}  // namespace raylab
