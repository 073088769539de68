// Internal to the glTF loader: glTF materials into MaterialRecords, either chosen explicitly in
// extras.raylab or mapped from the core metallic-roughness model (docs/scenes.md), and their base-colour
// textures into RGBA8 images.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "gltf_read/gltf_document.h"
#include "scene/scene.h"

namespace raylab::gltf {

// The inputs of the metallic-roughness mapping, as the core material and its KHR_materials_ior and
// KHR_materials_transmission extensions give them (glTF's defaults).
struct MetallicRoughness {
  glm::vec3 baseColor{1.0f};
  float metallic = 1.0f;
  float roughness = 1.0f;
  float ior = 1.5f;
  float transmission = 0.0f;
  float specular = 1.0f;                // KHR_materials_specular.specularFactor
  glm::vec3 specularColor{1.0f};        // KHR_materials_specular.specularColorFactor
  float clearcoat = 0.0f;               // KHR_materials_clearcoat.clearcoatFactor
  float clearcoatRoughness = 0.0f;      // KHR_materials_clearcoat.clearcoatRoughnessFactor
  float iridescence = 0.0f;             // KHR_materials_iridescence.iridescenceFactor
  float iridescenceIor = 1.3f;          // KHR_materials_iridescence.iridescenceIor
  float iridescenceThicknessNm = 400.0f;  // KHR_materials_iridescence.iridescenceThicknessMaximum
  float iridescenceThicknessMinimumNm = 100.0f;  // its minimum: where iridescenceThicknessTexture's G is 0
  float volumeThickness = 0.0f;         // KHR_materials_volume.thicknessFactor (0: thin-walled, no volume)
  float attenuationDistance = std::numeric_limits<float>::infinity();  // KHR_materials_volume
  glm::vec3 attenuationColor{1.0f};     // KHR_materials_volume.attenuationColor
  float dispersion = 0.0f;              // KHR_materials_dispersion.dispersion, 20 / the Abbe number
  // The OpenPBR-aligned drafts, which name openpbr's own parameters: KHR_materials_coat (it replaces the clear coat
  // where both appear), KHR_materials_fuzz (it replaces the sheen), KHR_materials_diffuse_roughness.
  bool hasCoat = false;
  float coat = 0.0f, coatRoughness = 0.0f, coatIor = 1.5f, coatDarkening = 1.0f, coatAnisotropy = 0.0f;
  float coatAnisotropyRotation = 0.0f;  // radians from the tangent, wrapped to [-pi, pi]
  float anisotropyRotation = 0.0f;  // KHR_materials_anisotropy, radians from the tangent towards the bitangent
  float diffuseTransmission = 0.0f;  // KHR_materials_diffuse_transmission
  glm::vec3 diffuseTransmissionColor{1.0f};
  glm::vec3 coatColor{1.0f};
  bool hasFuzz = false;
  float fuzz = 0.0f, fuzzRoughness = 0.5f;
  glm::vec3 fuzzColor{1.0f};
  float diffuseRoughness = 0.0f;
  float anisotropy = 0.0f;              // KHR_materials_anisotropy.anisotropyStrength
  glm::vec3 sheenColor{0.0f};           // KHR_materials_sheen.sheenColorFactor
  float sheenRoughness = 0.0f;          // KHR_materials_sheen.sheenRoughnessFactor
};

// glass (eta = ior, tint = base colour) when transmission is 1 without a volume; openpbr when a clear coat, an
// iridescent film or a sheen covers any of it, or its transmission is partial or has a volume (docs/gltf.md, "Material extensions"); else gltf_pbr, glTF's own BRDF, with the factors as they
// are (an ior above gltf_pbr's 3 is used as 3, with a warning). `where` starts error messages.
gpu::MaterialRecord mapMetallicRoughness(const MetallicRoughness& input, const std::string& where);

// Applies an extras.raylab material object to `record`: "model" (optional) restarts from that model's
// defaults, every other key must be a parameter of the model or "delta", RGB values written [r, g, b].
// A file parameter ("file": "x.binary", measured) is a URI of `document`: relative to its folder and inside it.
// Throws Error starting with `where` for unknown models or keys, wrong JSON types and out-of-range values.
void applyRaylabMaterial(gpu::MaterialRecord& record, const nlohmann::json& raylab, const std::string& where,
                         Document* document = nullptr);

// Fills scene.materials so that scene material i is glTF material i, and scene.textures with the base-colour
// textures they use.
void convertMaterials(Document& document, Scene& scene);

// The material of primitives and spheres without one, appended to scene.materials on first use.
class DefaultMaterial {
 public:
  std::uint32_t index(Scene& scene);

 private:
  std::int64_t index_ = -1;
};

}  // namespace raylab::gltf
