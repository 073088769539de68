#include "image/path_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render/kernel_features.h"
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
                    std::uint32_t spp, int regionsX, int regionsY) {
  const std::size_t regions = std::size_t(regionsX * regionsY);
  std::vector<std::vector<double>> differences(regions);
  double level = 0.0;
  for (std::uint32_t run = 1; run <= runs; ++run) {
    a.seed = b.seed = run;
    const std::vector<double> ma = regionMeans(renderImage(device, scene, a, spp), regionsX, regionsY);
    const std::vector<double> mb = regionMeans(renderImage(device, scene, b, spp), regionsX, regionsY);
    for (std::size_t i = 0; i < regions; ++i) {
      differences[i].push_back(ma[i] - mb[i]);
      level += ma[i] / double(regions * runs);
    }
  }
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
