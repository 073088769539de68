// Lets one header declare structs and constants for both C++ (glm) and GLSL, so host and device never
// disagree on a layout. Buffers use the scalar block layout (GL_EXT_scalar_block_layout) on the device,
// which matches the tightly packed C++ structs; every struct gets a static_assert on its size.
#ifndef RAYLAB_SHARED_COMPAT_H
#define RAYLAB_SHARED_COMPAT_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define RL_NAMESPACE_BEGIN \
  namespace raylab::gpu {  \
  using uint = std::uint32_t; \
  using glm::vec2;           \
  using glm::vec3;           \
  using glm::vec4;            \
  using glm::uvec2;          \
  using glm::uvec3;          \
  using glm::uvec4;
#define RL_NAMESPACE_END }
#define RL_CONST inline constexpr
#define RL_CHECK_SIZE(type, bytes) static_assert(sizeof(type) == (bytes), #type " must match its GLSL layout")
#else
#define RL_NAMESPACE_BEGIN
#define RL_NAMESPACE_END
#define RL_CONST const
#define RL_CHECK_SIZE(type, bytes)
#endif

#endif
