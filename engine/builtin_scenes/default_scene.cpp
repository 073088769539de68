#include "builtin_scenes/default_scene.h"

#include <string_view>

#include "gltf_read/gltf_loader.h"

namespace raylab {

namespace embedded {
std::string_view showcaseGltf();  // generated from assets/scenes/showcase.gltf by engine/CMakeLists.txt
}  // namespace embedded

Scene makeDefaultScene(const GltfOptions& options) {
  return loadGltfText(std::string(embedded::showcaseGltf()), "", "showcase", options);
}

}  // namespace raylab
