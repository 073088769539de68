// What the path integrator's image tests share: settings for a path-traced render, materials by parameter
// name, and the t-test of two estimators of one image over regions of it.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "vk/device.h"

namespace raylab::test {

// Pixel centres of a size x size image, the path integrator specialised for `scene`.
RenderSettings pathSettings(std::uint32_t size, std::uint32_t maxDepth, const Scene& scene);
// The same, jittered, with `sampling` (gpu::kSampling...).
RenderSettings samplingSettings(std::uint32_t size, std::uint32_t maxDepth, const Scene& scene,
                                std::uint32_t sampling);

// A model's default record with the named parameters set (grey values).
gpu::MaterialRecord material(const char* model, std::vector<std::pair<const char*, float>> params);

// Mean of channel g over each of regionsX x regionsY regions of an image, row by row.
std::vector<double> regionMeans(const Image& image, int regionsX, int regionsY);

// The largest |t| over the regions of the difference between two estimators of one image (settings a and b),
// from `runs` independent pairs of renders (seeds 1..runs): the run-to-run spread gives the standard error,
// heavy-tailed samples included. Differences below 1e-5 of the image's mean are float rounding, not bias.
// With `otherBackend`, run 1 also checks that the other backend renders both estimators' first samples bit for bit.
double worstRegionT(const Device& device, const Scene& scene, RenderSettings a, RenderSettings b, std::uint32_t runs,
                    std::uint32_t spp, int regionsX = 4, int regionsY = 4, bool otherBackend = true);

}  // namespace raylab::test
