#include "scene/load_scene.h"

#include "scene/default_scene.h"
#include "scene/gltf_loader.h"

namespace raylab {

Scene loadScene(const SceneRequest& request) {
  if (request.path.empty()) return makeDefaultScene(request.camera);
  return loadGltfFile(request.path, GltfOptions{request.camera});
}

}  // namespace raylab
