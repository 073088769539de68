#include "scene/default_scene.h"

#include "scene/shapes.h"

namespace raylab {

Scene makeDefaultScene() {
  Scene scene;
  scene.name = "default";
  scene.camera.name = "default";
  scene.camera.position = {0.0f, 2.2f, 7.5f};
  scene.camera.target = {0.0f, 0.6f, 0.0f};
  scene.camera.yfov = glm::radians(38.0f);
  scene.background = {0.02f, 0.025f, 0.035f};

  scene.materials = {
      {"ground", lambertMaterial({0.6f, 0.6f, 0.6f})},
      {"red", lambertMaterial({0.7f, 0.12f, 0.1f})},
      {"green", lambertMaterial({0.15f, 0.6f, 0.2f})},
      {"blue", lambertMaterial({0.12f, 0.2f, 0.7f})},
      {"mirror", lambertMaterial({0.9f, 0.9f, 0.9f}, 0.85f)},
  };
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.spheres = {
      {{-2.4f, 0.7f, 0.0f}, 0.7f, 1},
      {{-0.8f, 0.7f, 0.6f}, 0.7f, 4},
      {{0.8f, 0.7f, 0.0f}, 0.7f, 2},
      {{2.4f, 0.7f, 0.6f}, 0.7f, 3},
      {{0.0f, 0.35f, 2.2f}, 0.35f, 1},
  };
  scene.lights = {
      {"key", pointLight({-3.0f, 6.0f, 5.0f}, glm::vec3(60.0f))},
      {"fill", pointLight({4.0f, 3.0f, 3.0f}, glm::vec3(12.0f, 13.0f, 16.0f))},
  };
  return scene;
}

}  // namespace raylab
