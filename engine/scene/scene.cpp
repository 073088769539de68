#include "scene/scene.h"

namespace raylab {

gpu::MaterialRecord defaultMaterial(std::uint32_t model) {
  gpu::MaterialRecord record{};
  record.model = model;
  record.rhoD = glm::vec3(0.5f);
  record.rhoS = glm::vec3(0.5f);
  record.delta = 0.0f;
  record.tint = glm::vec3(1.0f);
  record.eta = 1.5f;
  record.s = 50.0f;
  record.m = 0.2f;
  record.alphaX = 0.2f;
  record.alphaY = 0.2f;
  record.nu = 100.0f;
  record.nv = 100.0f;
  record.baseColorTexture = -1;
  return record;
}

gpu::MaterialRecord lambertMaterial(glm::vec3 rhoD, float delta) {
  gpu::MaterialRecord record = defaultMaterial(gpu::kModelLambert);
  record.rhoD = rhoD;
  record.rhoS = glm::vec3(0.0f);
  record.delta = delta;
  return record;
}

gpu::LightRecord pointLight(glm::vec3 position, glm::vec3 intensity) {
  gpu::LightRecord record{};
  record.type = gpu::kLightPoint;
  record.position = position;
  record.intensity = intensity;
  record.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  record.cosInner = -1.0f;
  record.cosOuter = -1.0f;
  return record;
}

std::uint64_t triangleCount(const Scene& scene) {
  std::uint64_t count = 0;
  for (const MeshInstance& instance : scene.instances) count += scene.meshes[instance.mesh].indices.size() / 3;
  return count;
}

}  // namespace raylab
