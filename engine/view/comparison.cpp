#include "view/comparison.h"

#include "brdf_tables/brdf_tables.h"
#include "shared/bindings.h"
#include "vk/pipeline.h"

namespace raylab {

namespace {

KernelFeatures comparedKernel(const Scene& scene, const CompareSpec& spec, std::uint32_t integrator) {
  KernelFeatures kernel = featuresOf(withMaterial(scene, spec));
  kernel.integrator = integrator;
  return kernel;
}

// The right side's own BRDF tables: its material may use a measured file the scene does not.
void bindTables(const Device& device, const DeviceMaterials& records, Comparison& comparison) {
  if (updateBrdfTables(device, comparison.brdfTables, comparison.measuredFiles, records.measuredFiles)) {
    writeStorageBuffer(device, comparison.renderer.trace.descriptors.set, gpu::kBindingBrdfTables,
                       comparison.brdfTables.handle);
  }
}

}  // namespace

std::vector<Material> comparedMaterials(const Scene& scene, const CompareSpec& spec) {
  std::vector<Material> materials = scene.materials;
  materials.at(spec.material).record = spec.record;
  return materials;
}

Scene withMaterial(const Scene& scene, const CompareSpec& spec) {
  Scene compared = scene;
  compared.materials = comparedMaterials(scene, spec);
  return compared;
}

void startComparison(const Device& device, const GpuScene& gpuScene, const Scene& scene, RenderSettings settings,
                     std::uint32_t integrator, const CompareSpec& spec, Comparison& comparison) {
  stopComparison(device, comparison);
  settings.kernel = comparedKernel(scene, spec, integrator);
  const DeviceMaterials records = deviceMaterialsOf(comparedMaterials(scene, spec));
  comparison.materials = createBufferWithData<gpu::MaterialRecord>(device, records.records,
                                                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "compared materials");
  comparison.renderer = createRenderer(device, gpuScene, withMaterial(scene, spec), settings);
  writeStorageBuffer(device, comparison.renderer.trace.descriptors.set, gpu::kBindingMaterials,
                     comparison.materials.handle);
  bindTables(device, records, comparison);
  comparison.spec = spec;
  comparison.active = true;
}

void stopComparison(const Device& device, Comparison& comparison) {
  if (!comparison.active) return;
  destroyRenderer(device, comparison.renderer);
  destroyBuffer(device, comparison.materials);
  destroyBuffer(device, comparison.brdfTables);
  comparison = {};
}

void updateComparison(const Device& device, const Scene& scene, std::uint32_t integrator, Comparison& comparison) {
  if (!comparison.active) return;
  const DeviceMaterials records = deviceMaterialsOf(comparedMaterials(scene, comparison.spec));
  uploadBuffer<gpu::MaterialRecord>(device, comparison.materials, records.records);
  bindTables(device, records, comparison);
  const KernelFeatures wanted = comparedKernel(scene, comparison.spec, integrator);
  if (!(wanted == comparison.renderer.kernel)) {
    swapRenderPipelines(device, comparison.renderer, createRenderPipelines(device, comparison.renderer, wanted), wanted);
  }
}

std::string leftLabel(const Scene& scene, const Comparison& comparison) {
  const Material& material = scene.materials.at(comparison.spec.material);
  return "A  " + material.name + ": " + describeRecord(material.record);
}

std::string rightLabel(const Scene& scene, const Comparison& comparison) {
  return "B  " + scene.materials.at(comparison.spec.material).name + ": " + describeRecord(comparison.spec.record);
}

}  // namespace raylab
