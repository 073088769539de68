#include "scene/load_scene.h"

#include <filesystem>

#include "scene/default_scene.h"
#include "scene/gltf_loader.h"

namespace raylab {

Scene loadScene(const SceneRequest& request) {
  if (request.path.empty()) return makeDefaultScene(request.camera);
  return loadGltfFile(request.path, GltfOptions{request.camera, request.allowOutsideUris});
}

std::string sceneName(const SceneRequest& request) {
  if (request.path.empty()) return "showcase";
  return std::filesystem::path(request.path).stem().string();
}

}  // namespace raylab
