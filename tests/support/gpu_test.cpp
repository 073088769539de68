#include "support/gpu_test.h"

#include <gtest/gtest.h>

#include "render/ray_probe.h"
#include "scene/gpu_scene.h"
#include "util/error.h"

namespace raylab::test {

Instance* GpuTest::instance_ = nullptr;
Device* GpuTest::device_ = nullptr;

void GpuTest::SetUpTestSuite() {
  if (device_ != nullptr) return;
  try {
    InstanceOptions options;
    options.validation = true;
    instance_ = new Instance(createInstance(options));
    const std::vector<DeviceReport> reports = surveyDevices(*instance_);
    device_ = new Device(createDevice(*instance_, reports[chooseDevice(reports, std::nullopt)]));
  } catch (const Error& error) {
    // Reported by SetUp for every test: a missing device must fail loudly, not skip.
    std::fprintf(stderr, "GpuTest: no usable Vulkan device: %s\n", error.what());
  }
}

void GpuTest::TearDownTestSuite() {
  if (device_ != nullptr) {
    destroyDevice(*device_);
    delete device_;
    device_ = nullptr;
  }
  if (instance_ != nullptr) {
    destroyInstance(*instance_);
    delete instance_;
    instance_ = nullptr;
  }
}

void GpuTest::SetUp() {
  ASSERT_NE(device_, nullptr) << "no Vulkan device with ray queries: run tools/setup.sh test";
  validationBefore_ = validationMessageCount();
}

void GpuTest::TearDown() {
  EXPECT_EQ(validationMessageCount(), validationBefore_) << "Vulkan validation messages were reported (see stderr)";
}

Image renderImage(const Device& device, const Scene& scene, const RenderSettings& settings, std::uint32_t spp) {
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, spp);
  // A NaN or Inf sample is a defect the kernel hides by dropping it: no test scene may have one.
  EXPECT_EQ(renderer.droppedSamples, 0u) << scene.name << ": NaN or Inf samples were dropped";
  Image image = readImage(device, renderer);
  destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  return image;
}

std::vector<gpu::ProbeHit> traceProbeRays(const Device& device, const Scene& scene,
                                          std::span<const gpu::ProbeRay> rays) {
  GpuScene gpuScene = uploadScene(device, scene);
  RayProbe probe = createRayProbe(device, gpuScene, static_cast<std::uint32_t>(rays.size()));
  std::vector<gpu::ProbeHit> hits = traceRays(device, probe, rays);
  destroyRayProbe(device, probe);
  destroyGpuScene(device, gpuScene);
  return hits;
}

}  // namespace raylab::test
