#include "brdf_eval/lobe.h"

#include <cmath>
#include <cstdio>

#include "brdf_params/material_params.h"
#include "reference/albedo.h"
#include "reference/brdf_reference.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 inPlane(double thetaDegrees, bool twoSided = false) {
  const double theta = thetaDegrees * kPi / 180.0;
  // cos(+-90 degrees) is 6e-17 in double: the horizon's samples lie a hair above the surface, never below (a
  // two-sided plot goes on below it).
  const double cosine = std::cos(theta);
  return glm::vec3(float(std::sin(theta)), 0.0f, float(twoSided ? cosine : std::max(0.0, cosine)));
}

// "x y z" (a direction, or r g b), as `raylab brdf eval` reads vectors.
std::string vectorText(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "%.9g %.9g %.9g", double(v.x), double(v.y), double(v.z));
  return text;
}

bool isGlass(const gpu::MaterialRecord& material) { return isDeltaOnly(material.model); }

}  // namespace

bool lobeIsTwoSided(const gpu::MaterialRecord& material) { return isTwoSided(modelInfo(material.model)); }

float lobeAngleDegrees(std::uint32_t sample, bool twoSided) {
  if (twoSided) return -180.0f + 360.0f * float(sample) / float(kLobeSamplesTwoSided);
  return -90.0f + 180.0f * float(sample) / float(kLobeSamples - 1);
}

std::vector<gpu::BrdfEvalCase> lobeCases(const gpu::MaterialRecord& material, float thetaIDegrees) {
  const bool twoSided = lobeIsTwoSided(material);
  std::vector<gpu::BrdfEvalCase> cases(twoSided ? kLobeSamplesTwoSided : kLobeSamples);
  const glm::vec3 wi = inPlane(-double(thetaIDegrees));
  for (std::uint32_t i = 0; i < cases.size(); ++i) {
    gpu::BrdfEvalCase& c = cases[i];
    c.material = material;
    c.wi = wi;
    c.wo = inPlane(lobeAngleDegrees(i, twoSided), twoSided);
    c.n = glm::vec3(0.0f, 0.0f, 1.0f);
    c.t = glm::vec3(1.0f, 0.0f, 0.0f);
  }
  return cases;
}

std::vector<glm::vec3> lobeValues(std::span<const gpu::BrdfEvalCase> cases, std::span<const gpu::BrdfEvalValue> values) {
  std::vector<glm::vec3> fcos(cases.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < cases.size() && i < values.size(); ++i) {
    if (isGlass(cases[i].material)) continue;
    fcos[i] = values[i].f * std::abs(cases[i].wo.z);  // one-sided cases lie on or above the horizon
  }
  return fcos;
}

AlbedoCurve albedoCurve(const gpu::MaterialRecord& material) {
  AlbedoCurve curve;
  if (isGlass(material)) return curve;
  const reference::Material reference = reference::fromRecord(material);
  reference::AlbedoOptions options;
  options.relTolerance = 1e-4;
  options.maxRegions = 4000;
  for (std::uint32_t i = 0; i < kAlbedoSamples; ++i) {
    const double degrees = 90.0 * i / (kAlbedoSamples - 1);
    // Exactly at the horizon the albedo is a limit: evaluate a hair above it.
    const double theta = std::min(degrees, 89.9) * kPi / 180.0;
    const reference::Albedo albedo = reference::directionalAlbedo(reference, reference::directionFromAngles(theta, 0.0), options);
    curve.thetaDegrees.push_back(float(degrees));
    curve.albedo.push_back(glm::vec3(albedo.value));
  }
  return curve;
}

std::string formatLobeCsv(const gpu::MaterialRecord& material, float thetaIDegrees,
                          std::span<const gpu::BrdfEvalCase> cases, std::span<const gpu::BrdfEvalValue> values,
                          const AlbedoCurve& albedo) {
  std::string text = "# " + std::string(modelInfo(material.model).name) + " lobe at theta_i = " +
                     std::to_string(thetaIDegrees) + " degrees: n = 0 0 1, t = 1 0 0 (docs/viewer.md)\n";
  text += "kind,theta_i,theta_o,wi,wo,f,fcos\n";
  const std::vector<glm::vec3> fcos = lobeValues(cases, values);
  char angles[64];
  for (std::size_t i = 0; i < cases.size() && i < values.size(); ++i) {
    std::snprintf(angles, sizeof angles, "%.9g,%.9g", double(thetaIDegrees),
                  double(lobeAngleDegrees(std::uint32_t(i), lobeIsTwoSided(material))));
    text += "lobe," + std::string(angles) + "," + vectorText(cases[i].wi) + "," + vectorText(cases[i].wo) + "," +
            vectorText(isGlass(material) ? glm::vec3(0.0f) : values[i].f) + "," + vectorText(fcos[i]) + "\n";
  }
  for (std::size_t i = 0; i < albedo.thetaDegrees.size(); ++i) {
    std::snprintf(angles, sizeof angles, "%.9g", double(albedo.thetaDegrees[i]));
    text += "albedo,," + std::string(angles) + ",,,," + vectorText(albedo.albedo[i]) + "\n";
  }
  return text;
}

}  // namespace raylab
