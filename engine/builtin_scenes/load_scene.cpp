#include "builtin_scenes/load_scene.h"

#include <filesystem>
#include <new>

#include "builtin_scenes/default_scene.h"
#include "gltf_read/gltf_loader.h"
#include "util/error.h"

namespace raylab {

Scene loadScene(const SceneRequest& request) {
  const GltfOptions options{request.camera,          request.allowOutsideUris,   request.environment,
                            request.environmentStrength, request.environmentRotation, request.maxBufferBytes};
  if (request.path.empty()) return makeDefaultScene(options);
  try {
    return loadGltfFile(request.path, options);
  } catch (const std::bad_alloc&) {
    // The limits of docs/scenes.md should stop this first; if not, still say which file asked for too much.
    throw Error(request.path + ": out of memory while loading the scene (it asks for more than this machine has; "
                               "see the limits in docs/scenes.md)");
  }
}

std::string sceneName(const SceneRequest& request) {
  if (request.path.empty()) return "showcase";
  return std::filesystem::path(request.path).stem().string();
}

}  // namespace raylab
