// The scene `raylab render` draws when no file is given: it needs no asset on disk.
#pragma once

#include "scene/scene.h"

namespace raylab {

// A ground plane, a row of spheres (one a mirror), two point lights and a camera.
Scene makeDefaultScene();

}  // namespace raylab
