#include "support/gpu_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "render/ray_probe.h"
#include "render/gpu_scene.h"
#include "shared/features.h"
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
  ASSERT_NE(device_, nullptr) << "no Vulkan device with ray tracing: run tools/setup.sh test";
  // The tests cross-check the two backends on every render: the reference device (lavapipe) has both.
  ASSERT_TRUE(device_->rayQueries && device_->rayTracingPipelines)
      << device_->report.name << " lacks ray queries or ray-tracing pipelines; the tests need both backends";
  validationBefore_ = validationMessageCount();
}

void GpuTest::TearDown() {
  EXPECT_EQ(validationMessageCount(), validationBefore_) << "Vulkan validation messages were reported (see stderr)";
}

namespace {

// Samples of every test render that the other backend renders too, to be compared bit for bit.
constexpr std::uint32_t kBackendParitySpp = 2;

// FNV-1a over raw bytes.
void hashBytes(std::uint64_t& hash, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
}

// What makes a test scene what it is (its name, materials, lights, spheres, meshes, camera), the image size and
// the integrator: renders that differ only in seed, sample count or sampling strategy share it.
std::uint64_t sceneKey(const Scene& scene, const RenderSettings& settings) {
  std::uint64_t hash = 14695981039346656037ull;
  hashBytes(hash, scene.name.data(), scene.name.size());
  for (const Material& material : scene.materials) hashBytes(hash, &material.record, sizeof material.record);
  for (const Light& light : scene.lights) hashBytes(hash, &light.record, sizeof light.record);
  for (const Sphere& sphere : scene.spheres) hashBytes(hash, &sphere, sizeof sphere);
  for (const Mesh& mesh : scene.meshes) hashBytes(hash, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  hashBytes(hash, &scene.camera.position, sizeof scene.camera.position);
  hashBytes(hash, &scene.camera.target, sizeof scene.camera.target);
  const std::uint32_t size[4] = {settings.width, settings.height, settings.maxDepth,
                                 settings.kernel ? settings.kernel->integrator : gpu::kIntegratorSlides};
  hashBytes(hash, size, sizeof size);
  return hash;
}

// Each test scene is cross-checked on the other backend once per test program and integrator, on its first
// render: repeated renders of one scene (seeds, sampling strategies) would add little but the other backend's
// compilation time.
bool firstRenderOf(const Scene& scene, const RenderSettings& settings) {
  static std::set<std::uint64_t> checked;
  return checked.insert(sceneKey(scene, settings)).second;
}

Backend otherBackend(Backend backend) { return backend == Backend::kQuery ? Backend::kPipeline : Backend::kQuery; }

// The same scene, settings and first `spp` samples on the other backend give the same image, bit for bit: both
// run the same GLSL programs with the same arithmetic on the same traversal.
void expectSameOnOtherBackend(const Device& device, const GpuScene& gpuScene, const Scene& scene,
                              RenderSettings settings, std::uint32_t spp, const Image& expected) {
  settings.backend = otherBackend(settings.backend);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  renderSamples(device, renderer, spp);
  const Image image = readImage(device, renderer);
  destroyRenderer(device, renderer);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    if (std::memcmp(&image.rgba[i], &expected.rgba[i], sizeof(float)) != 0) ++differing;
  }
  EXPECT_EQ(differing, 0u) << scene.name << ": " << differing << " of " << image.rgba.size()
                           << " channel values differ between the query and the pipeline backend at " << spp
                           << " spp";
}

}  // namespace

Image renderImage(const Device& device, const Scene& scene, const RenderSettings& settings, std::uint32_t spp) {
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderer = createRenderer(device, gpuScene, scene, settings);
  if (firstRenderOf(scene, settings)) {
    const std::uint32_t paritySpp = std::min(spp, kBackendParitySpp);
    renderSamples(device, renderer, paritySpp);
    expectSameOnOtherBackend(device, gpuScene, scene, settings, paritySpp, readImage(device, renderer));
    renderSamples(device, renderer, spp - paritySpp);
  } else {
    renderSamples(device, renderer, spp);
  }
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
  std::vector<gpu::ProbeHit> hits[2];
  for (Backend backend : {Backend::kQuery, Backend::kPipeline}) {
    RayProbe probe = createRayProbe(device, gpuScene, static_cast<std::uint32_t>(rays.size()), backend);
    hits[int(backend)] = traceRays(device, probe, rays);
    destroyRayProbe(device, probe);
  }
  destroyGpuScene(device, gpuScene);
  // Both backends find the same hits, bit for bit (distances, ids, reconstructed points and normals).
  EXPECT_EQ(std::memcmp(hits[0].data(), hits[1].data(), hits[0].size() * sizeof(gpu::ProbeHit)), 0)
      << scene.name << ": the query and the pipeline backend's probes disagree";
  return hits[0];
}

}  // namespace raylab::test
