// The host-side scene: what a glTF file or the built-in scene describes, before it is uploaded.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/environment.h"
#include "shared/scene_records.h"

namespace raylab {

// The vertical field of view a camera may have, radians, checked as the float the renderer keeps: below 1e-4
// the pixel footprint underflows, at pi the image plane is infinite. glTF, the viewer and Python share it.
inline constexpr float kMinYfov = 1e-4f;
inline constexpr float kMaxYfov = 3.1f;

struct Camera {
  std::string name;
  glm::vec3 position{0.0f, 1.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = glm::radians(40.0f);  // vertical field of view, radians
};

// An indexed triangle mesh in its own object space. Normals and UVs are either empty or one per position.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;          // TEXCOORD_0
  std::vector<glm::vec2> uvs1;         // TEXCOORD_1, when a material reads it
  std::vector<glm::vec4> tangents;     // xyz and the bitangent's sign w, when a normal map needs them
  std::vector<std::uint32_t> indices;  // three per triangle
};

struct MeshInstance {
  std::uint32_t mesh = 0;
  glm::mat4 transform{1.0f};  // object to world
  std::uint32_t material = 0;
};

// An exact sphere in world space, traced through AABB geometry.
struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  std::uint32_t material = 0;
};

struct Material {
  std::string name;
  gpu::MaterialRecord record;
};

// An RGBA image as its file stores it, 8 or 16 bits a channel, rows from the top; each use says whether it is sRGB
// colour or data (gpu::TextureRef, gpu::MaterialTextures).
struct Texture {
  std::string name;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;     // 4 bytes per texel, or empty for a 16-bit image
  std::vector<std::uint16_t> rgba16;  // a 16-bit image (a normal map's precision): 4 values per texel
  std::uint32_t wrapS = gpu::kWrapRepeat;
  std::uint32_t wrapT = gpu::kWrapRepeat;
  bool nearest = false;            // glTF magFilter NEAREST: no bilinear filtering
};

// A punctual light as a scene describes it (KHR_lights_punctual, or the headlight); the device sees it as one
// gpu::LightRecord among all the lights (engine/render/light_records.h).
struct PunctualLight {
  std::uint32_t type = gpu::kLightPoint;  // gpu::kLightPoint, kLightSpot, kLightDirectional or kLightHeadlight
  glm::vec3 position{0.0f};   // point, spot; the headlight: its offset along the camera's right, up and forward
  glm::vec3 intensity{0.0f};  // RGB radiant intensity in W/sr (point, spot, headlight) or irradiance in W/m^2
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot, directional: the direction light travels, unit length
  float cosInner = -1.0f;     // spot: full intensity inside this cone
  float cosOuter = -1.0f;     // spot: no light outside this cone
};

struct Light {
  std::string name;
  PunctualLight record;
};

struct Scene {
  std::string name;
  Camera camera;
  std::vector<std::string> cameraNames;  // every camera the file offers (--camera NAME), in the file's order
  std::vector<Mesh> meshes;
  std::vector<MeshInstance> instances;
  std::vector<Sphere> spheres;
  std::vector<Material> materials;   // MaterialRecord.textures indexes `materialTextures`
  std::vector<gpu::MaterialTextures> materialTextures;  // TextureRef.texture indexes `textures`
  std::vector<Texture> textures;
  std::vector<Light> lights;
  glm::vec3 background{0.0f};  // radiance of rays that leave the scene, when there is no environment image
  Environment environment;     // extras.raylab.environment or --env (docs/integrators.md)
};

gpu::MaterialRecord lambertMaterial(glm::vec3 rhoD, float delta = 0.0f);

// A use of no texture, and a use of `texture` on TEXCOORD_0 without a transform.
gpu::TextureRef noTextureRef();
gpu::TextureRef textureRef(int texture);
// A MaterialTextures record with no texture in any use, opaque.
gpu::MaterialTextures noMaterialTextures();
// True when the material is alpha-tested or blended, or its model's opacity (openpbr's geometry_opacity) is below 1:
// its meshes are non-opaque geometry, and the kernel needs the alpha feature.
bool hasAlpha(const Scene& scene, const gpu::MaterialRecord& record);
// True when the material reads textures of glTF's layered extensions (its layers' parameters) or turns its
// anisotropy's direction (MaterialTextures::anisotropyRotation): the kernel needs the layer-texture feature, which
// costs a textured openpbr kernel about a third more compile time.
bool hasLayerTextures(const Scene& scene, const gpu::MaterialRecord& record);

// True when some mesh instance or sphere has a material with emission > 0 (the path integrator's emitters).
bool emits(const Scene& scene, std::uint32_t material);
bool hasEmissiveGeometry(const Scene& scene);

PunctualLight pointLight(glm::vec3 position, glm::vec3 intensity);
// The registered name of a light kind (shaders/lights/lights.cmake): "point", "spot", "directional", "headlight",
// ...; the names `raylab info`, Python and the docs use.
const char* lightTypeName(std::uint32_t type);

std::uint64_t triangleCount(const Scene& scene);

}  // namespace raylab
