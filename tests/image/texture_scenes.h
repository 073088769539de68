// What the texture image tests build their scenes from: a UV-mapped quad and a texture from its texels.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace raylab::test {

// A quad of half-size `half` in the y = 0 plane facing +y, UVs (0, 0) to (1, 1) with u along +x and v along +z.
inline Mesh texturedQuad(float half = 1.0f) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
  mesh.normals.assign(4, glm::vec3(0, 1, 0));
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from +y
  return mesh;
}

// An RGBA8 texture of width x height texels, rows from the top.
inline Texture solidTexture(std::vector<std::uint8_t> rgba, std::uint32_t width = 1, std::uint32_t height = 1) {
  Texture texture;
  texture.name = "texels";
  texture.width = width;
  texture.height = height;
  texture.rgba = std::move(rgba);
  return texture;
}

}  // namespace raylab::test
