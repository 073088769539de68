// Internal to the glTF loader: accessors into triangle meshes, with every byte range and index checked.
#pragma once

#include <vector>

#include "gltf_read/gltf_document.h"
#include "scene/scene.h"

namespace raylab::gltf {

// A glTF primitive as a raylab mesh (one mesh per primitive, since a raylab instance has one material).
struct PrimitiveMesh {
  Mesh mesh;
  int material = -1;  // glTF material index; -1: none
};

// The triangle primitives of glTF mesh `meshIndex`; points and lines are skipped (reported once), strips and
// fans become lists. Throws Error naming the mesh, primitive and accessor for anything malformed.
std::vector<PrimitiveMesh> convertMesh(Document& document, int meshIndex);

}  // namespace raylab::gltf
