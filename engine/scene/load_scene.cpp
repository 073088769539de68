#include "scene/load_scene.h"

#include "scene/default_scene.h"
#include "util/error.h"

namespace raylab {

Scene loadScene(const SceneRequest& request) {
  if (request.path.empty()) return makeDefaultScene();
  throw Error(request.path + ": scene files are not supported by this build yet; run without SCENE for the built-in scene");
}

}  // namespace raylab
