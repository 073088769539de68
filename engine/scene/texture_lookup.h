// The CPU reference of a material texture lookup (shaders/kernel/textures.glsl), written for clarity in double
// precision: a use's UV set through its KHR_texture_transform, glTF's wrap modes, bilinear or nearest filtering,
// sRGB decoding of colour uses before filtering. The GPU parity test compares the kernel against it, and the
// light-selection distribution weighs emissive textures with it (engine/render/light_records.cpp).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

// IEC 61966-2-1: an sRGB-encoded value in [0, 1] to linear.
double srgbToLinear(double encoded);

// The UV `ref` reads at a point with TEXCOORD_0 uv0 and TEXCOORD_1 uv1.
glm::dvec2 textureUv(const gpu::TextureRef& ref, glm::dvec2 uv0, glm::dvec2 uv1);

// RGBA of `texture` at uv (v grows downwards from the top row), decoded from sRGB when `srgb` (alpha never is).
glm::dvec4 sampleTexture(const Texture& texture, glm::dvec2 uv, bool srgb);

}  // namespace raylab
