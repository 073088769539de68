// Test fixture for everything that runs on the Vulkan device: one instance and device per test program,
// validation always on, and a test fails if any validation message appeared while it ran. No capable device
// is a failure, never a skip.
#pragma once

#include <gtest/gtest.h>

#include <span>
#include <vector>

#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "shared/frame.h"
#include "vk/device.h"

namespace raylab::test {

class GpuTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite();
  static void TearDownTestSuite();
  void SetUp() override;
  void TearDown() override;

  static const Device& device() { return *device_; }

 private:
  static Instance* instance_;
  static Device* device_;
  std::uint32_t validationBefore_ = 0;
};

// Uploads `scene`, renders `spp` samples on settings.backend and returns the mean radiance image.
// Every render also checks that the kernel dropped no NaN or Inf sample, and the first render of each scene in a
// test program that the other backend renders the same first samples bit for bit.
Image renderImage(const Device& device, const Scene& scene, const RenderSettings& settings, std::uint32_t spp);

// Traces rays against `scene` with the renderer's traversal, on both backends, which must agree bit for bit.
std::vector<gpu::ProbeHit> traceProbeRays(const Device& device, const Scene& scene,
                                          std::span<const gpu::ProbeRay> rays);

}  // namespace raylab::test
