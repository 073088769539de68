#include "image/path_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/renderer.h"
#include "brdf_params/material_params.h"
#include "shared/features.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {

RenderSettings pathSettings(std::uint32_t size, std::uint32_t maxDepth, const Scene& scene) {
  RenderSettings settings = pixelCentres(size, size);
  settings.maxDepth = maxDepth;
  KernelFeatures kernel = featuresOf(scene);
  kernel.integrator = gpu::kIntegratorPath;
  settings.kernel = kernel;
  return settings;
}

RenderSettings samplingSettings(std::uint32_t size, std::uint32_t maxDepth, const Scene& scene,
                                std::uint32_t sampling) {
  RenderSettings settings = pathSettings(size, maxDepth, scene);
  settings.kernel->sampling = sampling;
  settings.jitter = true;
  return settings;
}

gpu::MaterialRecord material(const char* model, std::vector<std::pair<const char*, float>> params) {
  gpu::MaterialRecord record = defaultRecord(findModel(model)->id);
  for (const auto& [name, value] : params) setParam(record, name, glm::vec3(value), "test");
  return record;
}

std::vector<double> regionMeans(const Image& image, int regionsX, int regionsY) {
  std::vector<double> means(std::size_t(regionsX * regionsY), 0.0);
  std::vector<int> counts(means.size(), 0);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const int region = int(y * regionsY / image.height) * regionsX + int(x * regionsX / image.width);
      means[std::size_t(region)] += image.at(x, y).g;
      counts[std::size_t(region)] += 1;
    }
  }
  for (std::size_t i = 0; i < means.size(); ++i) means[i] /= counts[i];
  return means;
}

double worstRegionT(const Device& device, const Scene& scene, RenderSettings a, RenderSettings b, std::uint32_t runs,
                    std::uint32_t spp, int regionsX, int regionsY, bool otherBackend) {
  const std::size_t regions = std::size_t(regionsX * regionsY);
  std::vector<std::vector<double>> differences(regions);
  double level = 0.0;
  // Run 1 through renderImage (which also checks the other backend bit for bit); the later runs reuse one renderer
  // per estimator with a new seed, since creating a renderer costs more than a small render.
  GpuScene gpuScene = uploadScene(device, scene);
  Renderer renderers[2] = {createRenderer(device, gpuScene, scene, a), createRenderer(device, gpuScene, scene, b)};
  const auto renderRun = [&](int which, const RenderSettings& settings, std::uint32_t run) {
    if (run == 1 && otherBackend) return renderImage(device, scene, settings, spp);
    Renderer& renderer = renderers[which];
    renderer.params.seed = run;
    resetAccumulation(device, renderer);
    renderSamples(device, renderer, spp);
    EXPECT_EQ(renderer.droppedSamples, 0u) << scene.name << ": NaN or Inf samples were dropped";
    return readImage(device, renderer);
  };
  for (std::uint32_t run = 1; run <= runs; ++run) {
    a.seed = b.seed = run;
    const std::vector<double> ma = regionMeans(renderRun(0, a, run), regionsX, regionsY);
    const std::vector<double> mb = regionMeans(renderRun(1, b, run), regionsX, regionsY);
    for (std::size_t i = 0; i < regions; ++i) {
      differences[i].push_back(ma[i] - mb[i]);
      level += ma[i] / double(regions * runs);
    }
  }
  for (Renderer& renderer : renderers) destroyRenderer(device, renderer);
  destroyGpuScene(device, gpuScene);
  double worst = 0.0;
  for (const std::vector<double>& d : differences) {
    double mean = 0.0, squares = 0.0;
    for (double v : d) mean += v;
    mean /= d.size();
    for (double v : d) squares += (v - mean) * (v - mean);
    const double standardError = std::sqrt(squares / (d.size() - 1) / d.size());
    // The black sky corners of a scene differ by 7e-7 between strategies (a few grazing floor pixels at the
    // horizon), a few ulps of their values: rounding, not bias.
    const double excess = std::max(0.0, std::abs(mean) - 1e-5 * level);
    if (standardError > 0.0) {
      worst = std::max(worst, excess / standardError);
    } else {
      EXPECT_EQ(mean, 0.0);  // a region the strategies estimate identically (the sky)
    }
  }
  return worst;
}

}  // namespace raylab::test
