// The fixed scenes of `raylab bench rays`: the same 64 spheres on a ground plane, tessellated to about 1k,
// 100k and 1M triangles, or traced as analytic spheres. One layout for all four, so the figures compare.
#pragma once

#include <span>
#include <string_view>

#include "scene/scene.h"

namespace raylab {

enum class BenchScene { kTriangles1k, kTriangles100k, kTriangles1M, kAnalyticSpheres };

struct BenchSceneInfo {
  BenchScene kind;
  std::string_view name;  // "1k triangles", used on the command line as e.g. "1k"
  std::string_view key;
};

std::span<const BenchSceneInfo> allBenchScenes();
Scene makeBenchScene(BenchScene kind);

// Every mesh's triangles in a random order (seeded): a file not in spatial order, as exporters and optimisers write.
void shuffleTriangles(Scene& scene, std::uint64_t seed);

}  // namespace raylab
