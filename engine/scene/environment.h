// The environment: an equirectangular HDR image (OpenEXR) around the scene, +Y up, lighting the path
// integrator and seen by rays that escape. Conventions in docs/integrators.md ("Environment light"): a world
// direction d looks up u = atan2(d.x, -d.z) / 2pi wrapped to [0, 1), v = acos(d.y) / pi, (0, 0) the top-left
// corner, bilinear between texel centres (Mitsuba 3's envmap with an identity transform).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

struct Environment {
  std::string path;        // the EXR file, for messages and the viewer's panel
  float strength = 1.0f;   // multiplies every texel
  float rotation = 0.0f;   // radians about +Y: the image turned counter-clockwise seen from above
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<glm::vec3> texels;  // linear RGB radiance, rows from the top; empty: no image
  float brightest = 0.0f;         // the largest channel of any texel, for the bound on strength x radiance

  bool hasImage() const { return !texels.empty(); }
};

// The rotation an environment may be given, degrees (glTF, --env-rotation, the viewer, Python).
inline constexpr float kMaxEnvironmentRotationDegrees = 360.0f;

// Largest environment image, in texels (16384 x 8192 half-float would be 768 MiB on the device).
inline constexpr std::uint64_t kMaxEnvironmentTexels = std::uint64_t(1) << 26;
inline constexpr std::uint64_t kMaxEnvironmentFileBytes = std::uint64_t(1) << 30;

// The bytes the device's environment buffer needs for a width x height image: its header, the texels and the
// sampling tables (render/gpu_scene.cpp lays them out). Known from an EXR header, before decoding.
std::uint64_t environmentBufferBytes(std::uint32_t width, std::uint32_t height);

// Reads the image at `path` (a regular OpenEXR file). Errors start with `where` and name the file: missing,
// not an EXR, too large, or a texel that is NaN or Inf (with its position). Negative values (lossy
// compression leaves a few) read as 0, with a warning. `strength` is checked against the image
// (scene/radiance_limits.h); that error starts with `strengthWhere` when given (the option that set it).
// An image whose environmentBufferBytes exceed `maxBufferBytes` (the device's maxStorageBufferRange, when known)
// is refused from its header, before gigabytes are decoded for a device that cannot hold them.
Environment loadEnvironment(const std::string& path, float strength, const std::string& where,
                            const std::string& strengthWhere = "",
                            std::uint64_t maxBufferBytes = std::numeric_limits<std::uint64_t>::max());

// The image of an OpenEXR file held in memory, checked as loadEnvironment checks it; `label` starts errors.
Environment decodeEnvironment(const std::string& bytes, const std::string& label,
                              std::uint64_t maxBufferBytes = std::numeric_limits<std::uint64_t>::max());

// The direction of (u, v) in the image's own frame, and back (before the rotation about +Y).
glm::vec3 environmentDirection(glm::vec2 uv);
glm::vec2 environmentUv(glm::vec3 direction);

}  // namespace raylab
