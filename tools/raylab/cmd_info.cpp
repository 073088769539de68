// `raylab info [SCENE]`: what a scene holds, by the names the other commands and the viewer's scripts take:
// cameras, materials with their model and parameters, lights, spheres, meshes and the environment.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "brdf_params/material_params.h"
#include "command_line/cli.h"
#include "commands.h"
#include "builtin_scenes/load_scene.h"
#include "shared/scene_records.h"
#include "util/error.h"

namespace raylab {

namespace {

std::string formatVector(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return text;
}

// "phong rho_d=0.7/0.1/0.1 rho_s=0.5 s=50 delta=0", in the syntax of `raylab brdf eval` and `--compare`.
std::string describeMaterial(const gpu::MaterialRecord& record) {
  std::string text = describeModelParams(record) + " delta=" + formatParamValue(glm::vec3(record.delta), false);
  if (std::max({record.emission.x, record.emission.y, record.emission.z}) > 0.0f) {
    text += " emission=" + formatParamValue(record.emission, true);
  }
  return text;
}

int info(const SceneRequest& request) {
  const Scene scene = loadScene(request);
  std::printf("scene: %s\n", scene.name.c_str());
  std::printf("cameras (%zu):", scene.cameraNames.size());
  for (const std::string& name : scene.cameraNames) {
    std::printf(" '%s'%s", name.c_str(), name == scene.camera.name ? " (used)" : "");
  }
  if (scene.cameraNames.empty()) std::printf(" none; the default view of the scene's bounds");
  std::printf("\n  used: '%s' at %s looking at %s, vertical field of view %.1f degrees\n", scene.camera.name.c_str(),
              formatVector(scene.camera.position).c_str(), formatVector(scene.camera.target).c_str(),
              double(scene.camera.yfov) * 180.0 / 3.14159265358979);
  std::printf("materials (%zu):\n", scene.materials.size());
  for (const Material& material : scene.materials) {
    std::printf("  '%s': %s\n", material.name.c_str(), describeMaterial(material.record).c_str());
  }
  std::printf("lights (%zu):\n", scene.lights.size());
  for (const Light& light : scene.lights) {
    const PunctualLight& r = light.record;
    std::printf("  '%s': %s", light.name.c_str(), lightTypeName(r.type));
    if (r.type == gpu::kLightHeadlight) {
      std::printf(" carried with the camera, offset %s (right, up, forward)", formatVector(r.position).c_str());
    } else if (r.type != gpu::kLightDirectional) {
      std::printf(" at %s", formatVector(r.position).c_str());
    }
    if (r.type == gpu::kLightSpot || r.type == gpu::kLightDirectional) {
      std::printf(" towards %s", formatVector(r.direction).c_str());
    }
    std::printf(", intensity %s", formatVector(r.intensity).c_str());
    if (r.type == gpu::kLightSpot) {
      std::printf(", cone %.1f to %.1f degrees", std::acos(double(r.cosInner)) * 180.0 / 3.14159265358979,
                  std::acos(double(r.cosOuter)) * 180.0 / 3.14159265358979);
    }
    std::printf("\n");
  }
  std::printf("spheres (%zu):\n", scene.spheres.size());
  for (const Sphere& sphere : scene.spheres) {
    std::printf("  centre %s, radius %g, material '%s'\n", formatVector(sphere.center).c_str(), double(sphere.radius),
                scene.materials.at(sphere.material).name.c_str());
  }
  std::printf("meshes: %zu, in %zu instances, %llu triangles\n", scene.meshes.size(), scene.instances.size(),
              static_cast<unsigned long long>(triangleCount(scene)));
  if (scene.environment.hasImage()) {
    std::printf("environment: %s (%ux%u), strength %g, rotation %g degrees\n", scene.environment.path.c_str(),
                scene.environment.width, scene.environment.height, double(scene.environment.strength),
                double(scene.environment.rotation) * 180.0 / 3.14159265358979);
  } else {
    std::printf("background: %s\n", formatVector(scene.background).c_str());
  }
  return kExitOk;
}

}  // namespace

void addInfoCommand(CLI::App& raylab) {
  auto request = std::make_shared<SceneRequest>();
  CLI::App* command = addCommand(
      raylab, "info",
      "list a scene's cameras, materials, lights and spheres\n"
      "Prints what SCENE (or, without SCENE, the built-in default scene) holds, by the names --camera, --compare "
      "and the viewer's scripts take: its cameras (and which one is used), each material with its BRDF model and "
      "parameters (in the syntax of `raylab brdf eval`), the lights, spheres, meshes and the environment.",
      [request] { return info(*request); });
  addSceneOptions(command, *request);
}

}  // namespace raylab
