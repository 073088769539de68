#include "bench/bench_scenes.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "scene/shapes.h"

namespace raylab {

namespace {

constexpr int kSpheresPerSide = 8;
constexpr float kSpacing = 1.25f;
constexpr float kRadius = 0.5f;

// (rings, segments) of each sphere's tessellation: 2 * rings * segments - 2 * segments triangles each.
struct Tessellation {
  std::uint32_t rings;
  std::uint32_t segments;
};

Tessellation tessellationFor(BenchScene kind) {
  switch (kind) {
    case BenchScene::kTriangles1k: return {3, 4};        // 16 triangles x 64 = 1k
    case BenchScene::kTriangles100k: return {28, 28};    // 1512 x 64 = 97k
    case BenchScene::kTriangles1M: return {88, 90};      // 15660 x 64 = 1.0M
    case BenchScene::kAnalyticSpheres: return {0, 0};
  }
  return {0, 0};
}

}  // namespace

std::span<const BenchSceneInfo> allBenchScenes() {
  static constexpr BenchSceneInfo kScenes[] = {
      {BenchScene::kTriangles1k, "1k triangles", "1k"},
      {BenchScene::kTriangles100k, "100k triangles", "100k"},
      {BenchScene::kTriangles1M, "1M triangles", "1m"},
      {BenchScene::kAnalyticSpheres, "64 analytic spheres", "spheres"},
  };
  return kScenes;
}

Scene makeBenchScene(BenchScene kind) {
  Scene scene;
  for (const BenchSceneInfo& info : allBenchScenes()) {
    if (info.kind == kind) scene.name = std::string(info.name);
  }
  scene.materials.push_back({"grey", lambertMaterial(glm::vec3(0.6f))});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  const Tessellation tessellation = tessellationFor(kind);
  for (int i = 0; i < kSpheresPerSide; ++i) {
    for (int j = 0; j < kSpheresPerSide; ++j) {
      const glm::vec3 center((i - 3.5f) * kSpacing, kRadius, (j - 3.5f) * kSpacing);
      if (kind == BenchScene::kAnalyticSpheres) {
        scene.spheres.push_back({center, kRadius, 0});
      } else {
        scene.meshes.push_back(makeUvSphere(center, kRadius, tessellation.rings, tessellation.segments));
        scene.instances.push_back({static_cast<std::uint32_t>(scene.meshes.size() - 1), glm::mat4(1.0f), 0});
      }
    }
  }
  scene.lights.push_back({"key", pointLight({4.0f, 8.0f, 6.0f}, glm::vec3(100.0f))});
  scene.camera.position = {0.0f, 6.5f, 9.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(45.0f);
  return scene;
}

void shuffleTriangles(Scene& scene, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  for (Mesh& mesh : scene.meshes) {
    const std::size_t triangles = mesh.indices.size() / 3;
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), random);
    std::vector<std::uint32_t> indices(mesh.indices.size());
    for (std::size_t k = 0; k < triangles; ++k) {
      for (int c = 0; c < 3; ++c) indices[3 * k + c] = mesh.indices[3 * order[k] + c];
    }
    mesh.indices = std::move(indices);
  }
}

}  // namespace raylab
