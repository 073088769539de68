#include "view_logic/scene_edits.h"

#include <cmath>
#include <optional>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"

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
  std::optional<glm::vec3> diffuse;   // the `diffuse` role (rho_d, Rd)
  std::optional<glm::vec3> specular;  // the `specular` role: a weight of the specular lobe
  std::optional<glm::vec2> alpha;     // roughness as RMS slopes along tangent and bitangent (Beckmann's m)
  std::optional<float> eta;
  std::optional<glm::vec3> transmittance;  // glass's tint, smooth or rough
};

// An exponent of R.wo (role mirror_exponent) is about a quarter of the exponent of N.H (role exponent) of the
// same lobe width.
constexpr float kMirrorToHalfwayExponent = 4.0f;

// Beckmann slope <-> Blinn-Phong exponent, the equivalence of Walter et al. 2007 (eq. 35): s = 2 / alpha^2 - 2.
float alphaOfExponent(float s) { return std::sqrt(2.0f / (s + 2.0f)); }
float exponentOfAlpha(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }

// The value of the parameter with `role`, if the model has one.
std::optional<glm::vec3> roleValue(const gpu::MaterialRecord& r, std::string_view role) {
  const ParamInfo* param = findRole(modelInfo(r.model), role);
  if (param == nullptr) return std::nullopt;
  return getParam(r, param->name);
}

Appearance appearanceOf(const gpu::MaterialRecord& r) {
  Appearance a;
  a.diffuse = roleValue(r, "diffuse");
  a.specular = roleValue(r, "specular");
  if (const auto eta = roleValue(r, "eta")) a.eta = eta->x;
  a.transmittance = roleValue(r, "transmittance");
  if (const auto m = roleValue(r, "slope")) a.alpha = glm::vec2(m->x);
  const auto alphaX = roleValue(r, "slope_x"), alphaY = roleValue(r, "slope_y");
  if (alphaX && alphaY) a.alpha = glm::vec2(alphaX->x, alphaY->x);
  if (const auto s = roleValue(r, "exponent")) a.alpha = glm::vec2(alphaOfExponent(s->x));
  if (const auto s = roleValue(r, "mirror_exponent")) a.alpha = glm::vec2(alphaOfExponent(kMirrorToHalfwayExponent * s->x));
  const auto nu = roleValue(r, "exponent_x"), nv = roleValue(r, "exponent_y");
  if (nu && nv) a.alpha = glm::vec2(alphaOfExponent(nu->x), alphaOfExponent(nv->x));
  return a;
}

// Sets the parameter with `role` to `value` clamped into its range (the mapping may leave it); a role the model
// lacks is skipped.
void carry(gpu::MaterialRecord& record, std::string_view role, glm::vec3 value) {
  const ParamInfo* param = findRole(modelInfo(record.model), role);
  if (param == nullptr || !std::isfinite(value.x + value.y + value.z)) return;
  setParam(record, param->name, glm::clamp(value, glm::vec3(param->min), glm::vec3(param->max)), "switchModel");
}

}  // namespace

void switchModel(gpu::MaterialRecord& record, std::uint32_t model) {
  const Appearance a = appearanceOf(record);
  gpu::MaterialRecord next = defaultRecord(model);
  next.delta = record.delta;
  next.textures = record.textures;
  setEmission(next, record.emission, "switchModel");  // a model with its own emission takes it as its parameters
  if (a.diffuse) carry(next, "diffuse", *a.diffuse);
  if (a.specular) carry(next, "specular", *a.specular);
  if (a.eta) carry(next, "eta", glm::vec3(*a.eta));
  if (a.transmittance) carry(next, "transmittance", *a.transmittance);
  if (a.alpha) {
    const glm::vec2 alpha = *a.alpha;
    const float isotropic = std::sqrt(alpha.x * alpha.y);
    carry(next, "slope", glm::vec3(isotropic));
    carry(next, "slope_x", glm::vec3(alpha.x));
    carry(next, "slope_y", glm::vec3(alpha.y));
    carry(next, "exponent_x", glm::vec3(exponentOfAlpha(alpha.x)));
    carry(next, "exponent_y", glm::vec3(exponentOfAlpha(alpha.y)));
    const float blinn = exponentOfAlpha(isotropic);
    carry(next, "exponent", glm::vec3(blinn));
    carry(next, "mirror_exponent", glm::vec3(blinn / kMirrorToHalfwayExponent));
  }
  // A material reading a file keeps its file when the new model reads the same kind (measured, nbrdf), else takes
  // the one of that kind most recently loaded (none yet: it has none, and the panel asks for one).
  if (const ParamInfo* file = findFileParam(modelInfo(model)); file != nullptr) {
    const ParamInfo* had = findFileParam(modelInfo(record.model));
    if (had != nullptr && had->role == file->role && record.params[had->slot] != 0.0f) {
      next.params[file->slot] = record.params[had->slot];
    } else {
      next.params[file->slot] = float(latestMeasuredFile(file->role));
    }
  }
  record = next;
}

}  // namespace raylab
