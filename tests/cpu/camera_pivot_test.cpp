// The CPU ray cast behind the viewer's picking and a glTF camera's pivot (scene/camera_pivot.h): it sees what the
// kernels' rays see, so a click through an alpha-masked hole picks what is behind it.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera_pivot.h"

namespace raylab {
namespace {

// A 2x2 quad in the y = 0 plane, UVs (0, 0) to (1, 1) with u along +x, v along +z.
Mesh quad() {
  Mesh mesh;
  mesh.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 2, 1, 0, 3, 2};
  return mesh;
}

// A quad at y = 1 of `alphaMode`, its base colour a 2x1 texture (nearest) opaque on the left (u < 0.5) and of
// alpha `rightAlpha` on the right, over an opaque floor at y = 0.
Scene quadOverFloor(std::uint32_t alphaMode, std::uint8_t rightAlpha) {
  Scene scene;
  scene.meshes = {quad(), quad()};
  Texture texture;
  texture.width = 2;
  texture.height = 1;
  texture.rgba = {255, 255, 255, 255, 255, 255, 255, rightAlpha};
  texture.nearest = true;
  scene.textures.push_back(texture);
  gpu::MaterialTextures uses = noMaterialTextures();
  uses.refs[gpu::kTextureBaseColor] = textureRef(0);
  uses.alphaMode = alphaMode;
  uses.alphaCutoff = 0.5f;
  scene.materialTextures.push_back(uses);
  scene.materials.push_back({"leaf", lambertMaterial(glm::vec3(0.5f))});
  scene.materials[0].record.textures = 0;
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.5f))});
  scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f)), 0});
  scene.instances.push_back({1, glm::mat4(1.0f), 1});
  return scene;
}

std::uint32_t pickedFromAbove(const Scene& scene, float x) {
  const std::optional<SceneHit> hit = firstHit(scene, {x, 5.0f, 0.1f}, {0.0f, -1.0f, 0.0f});
  EXPECT_TRUE(hit.has_value());
  return hit ? hit->material : 99u;
}

TEST(CameraPivot, RaysPassThroughAnAlphaMasksHoles) {
  const Scene scene = quadOverFloor(gpu::kAlphaMask, 0);
  EXPECT_EQ(pickedFromAbove(scene, -0.5f), 0u) << "the masked quad where it is solid";
  EXPECT_EQ(pickedFromAbove(scene, 0.5f), 1u) << "the floor through its hole";
  const std::optional<SceneHit> hit = firstHit(scene, {0.5f, 5.0f, 0.1f}, {0.0f, -1.0f, 0.0f});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->distance, 5.0f, 1e-5f);
}

TEST(CameraPivot, ABlendedSurfaceIsPickedWhereverItIsSeenAtAll) {
  EXPECT_EQ(pickedFromAbove(quadOverFloor(gpu::kAlphaBlend, 40), 0.5f), 0u) << "alpha 40/255: seen, so picked";
  EXPECT_EQ(pickedFromAbove(quadOverFloor(gpu::kAlphaBlend, 0), 0.5f), 1u) << "alpha 0: never seen";
  EXPECT_EQ(pickedFromAbove(quadOverFloor(gpu::kAlphaOpaque, 0), 0.5f), 0u) << "opaque ignores alpha";
}

}  // namespace
}  // namespace raylab
