#include "view_logic/scene_edits.h"

#include <cmath>
#include <optional>

#include "brdf_params/material_params.h"

namespace raylab {

Material* findMaterial(Scene& scene, std::string_view name) {
  for (Material& material : scene.materials) {
    if (material.name == name) return &material;
  }
  return nullptr;
}

Light* findLight(Scene& scene, std::string_view name) {
  for (Light& light : scene.lights) {
    if (light.name == name) return &light;
  }
  return nullptr;
}

namespace {

// What a material looks like in terms every model shares (docs/viewer.md, "Switching models"): the mapping a
// model switch carries over. Empty optionals: the old model has no such thing.
struct Appearance {
  std::optional<glm::vec3> diffuse;   // rho_d, Rd
  std::optional<glm::vec3> specular;  // rho_s of the models where it scales the specular lobe
  std::optional<glm::vec2> alpha;     // roughness as RMS slopes along tangent and bitangent (Beckmann's m)
  std::optional<float> eta;
};

// Phong's exponent s lobes about the mirror direction; Blinn-Phong's about the normal: s_blinn ~ 4 s_phong.
constexpr float kPhongToBlinn = 4.0f;

// Beckmann slope <-> Blinn-Phong exponent, the equivalence of Walter et al. 2007 (eq. 35): s = 2 / alpha^2 - 2.
float alphaOfExponent(float s) { return std::sqrt(2.0f / (s + 2.0f)); }
float exponentOfAlpha(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }

Appearance appearanceOf(const gpu::MaterialRecord& r) {
  Appearance a;
  switch (r.model) {
    case gpu::kModelLambert: a.diffuse = r.rhoD; break;
    case gpu::kModelPhong:
    case gpu::kModelBlinnPhong: {
      a.diffuse = r.rhoD;
      a.specular = r.rhoS;
      const float s = r.model == gpu::kModelPhong ? kPhongToBlinn * r.s : r.s;
      a.alpha = glm::vec2(alphaOfExponent(s));
      break;
    }
    case gpu::kModelCookTorrance:
      a.diffuse = r.rhoD, a.specular = r.rhoS, a.alpha = glm::vec2(r.m), a.eta = r.eta;
      break;
    case gpu::kModelWard:
    case gpu::kModelWardDuer:
    case gpu::kModelWardGmd:
      a.diffuse = r.rhoD, a.specular = r.rhoS, a.alpha = glm::vec2(r.alphaX, r.alphaY);
      break;
    case gpu::kModelAshikhminShirley:
      // Rs is the Fresnel reflectance at normal incidence, not a lobe's weight: it does not carry over.
      a.diffuse = r.rhoD, a.alpha = glm::vec2(alphaOfExponent(r.nu), alphaOfExponent(r.nv));
      break;
    case gpu::kModelGlass: a.eta = r.eta; break;
    default: break;
  }
  return a;
}

// Sets `name` to `value` clamped into its range (the mapping may leave it); a parameter the model lacks is skipped.
void carry(gpu::MaterialRecord& record, std::string_view name, glm::vec3 value) {
  const ParamInfo* param = findParam(modelInfo(record.model), name);
  if (param == nullptr || !std::isfinite(value.x + value.y + value.z)) return;
  setParam(record, name, glm::clamp(value, glm::vec3(param->min), glm::vec3(param->max)), "switchModel");
}

}  // namespace

void switchModel(gpu::MaterialRecord& record, std::uint32_t model) {
  const Appearance a = appearanceOf(record);
  gpu::MaterialRecord next = defaultRecord(model);
  next.delta = record.delta;
  next.baseColorTexture = record.baseColorTexture;
  next.emission = record.emission;
  if (a.diffuse) {
    carry(next, "rho_d", *a.diffuse);
    carry(next, "Rd", *a.diffuse);
  }
  if (a.specular) carry(next, "rho_s", *a.specular);
  if (a.eta) carry(next, "eta", glm::vec3(*a.eta));
  if (a.alpha) {
    const glm::vec2 alpha = *a.alpha;
    const float isotropic = std::sqrt(alpha.x * alpha.y);
    carry(next, "m", glm::vec3(isotropic));
    carry(next, "alpha_x", glm::vec3(alpha.x));
    carry(next, "alpha_y", glm::vec3(alpha.y));
    carry(next, "nu", glm::vec3(exponentOfAlpha(alpha.x)));
    carry(next, "nv", glm::vec3(exponentOfAlpha(alpha.y)));
    const float blinn = exponentOfAlpha(isotropic);
    carry(next, "s", glm::vec3(model == gpu::kModelPhong ? blinn / kPhongToBlinn : blinn));
  }
  record = next;
}

}  // namespace raylab
