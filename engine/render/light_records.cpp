#include "render/light_records.h"

#include <cmath>
#include <string>

#include "image/image.h"
#include "scene/camera_pivot.h"
#include "util/error.h"

namespace raylab {
namespace {

constexpr double kPi = 3.14159265358979323846;


// A punctual light's record. Its kind must be a delta light's: the selection takes every one of them.
gpu::LightRecord punctualRecord(const PunctualLight& light) {
  gpu::LightRecord record{};
  record.kind = light.type;
  record.p0 = light.position;
  record.p1 = light.direction;
  record.p2 = glm::vec3(light.cosInner, light.cosOuter, 0.0f);
  record.radiance = light.intensity;
  if (light.type >= gpu::kLightKindCount || !(gpu::kDeltaLightKinds & (1u << light.type))) {
    throw Error("light kind " + std::to_string(light.type) + " is not a punctual light");
  }
  return record;
}

// Powers (SceneLights.powers) are in watts of luminance, so that lights of different kinds compare (pbrt-v4's
// Light::Phi). A one-sided Lambertian emitter of radiance L_e and area A emits pi L_e A.
double surfacePower(const gpu::LightRecord& record) { return kPi * double(luminance(record.radiance)) * record.area; }

void addTriangleLights(const Scene& scene, const MeshInstance& instance, SceneLights& lights) {
  const Mesh& mesh = scene.meshes[instance.mesh];
  const glm::vec3 radiance = scene.materials[instance.material].record.emission;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    gpu::LightRecord record{};
    record.kind = gpu::kLightTriangle;
    record.p0 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i]], 1.0f));
    record.p1 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i + 1]], 1.0f));
    record.p2 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i + 2]], 1.0f));
    record.radiance = radiance;
    record.area = 0.5f * glm::length(glm::cross(record.p1 - record.p0, record.p2 - record.p0));
    lights.records.push_back(record);
    lights.powers.push_back(surfacePower(record));
  }
}

// One record per sphere (power 0 for those that do not emit), so that record = sphereFirstLight + primitive.
void addSphereLights(const Scene& scene, SceneLights& lights) {
  for (const Sphere& sphere : scene.spheres) {
    gpu::LightRecord record{};
    record.kind = gpu::kLightSphere;
    record.p0 = sphere.center;
    record.p1 = glm::vec3(sphere.radius, 0.0f, 0.0f);
    record.radiance = scene.materials[sphere.material].record.emission;
    record.area = float(4.0 * kPi * double(sphere.radius) * sphere.radius);
    lights.records.push_back(record);
    lights.powers.push_back(surfacePower(record));
  }
}

// The environment's radiance integrated over the sphere, 2 pi^2 fMean (environment_tables.h), through the disk of
// the scene's bounding sphere.
double environmentPower(const Environment& environment, const EnvironmentTables& tables, float sceneRadius) {
  const double integral = 2.0 * kPi * kPi * double(tables.fMean) * environment.strength;
  return kPi * double(sceneRadius) * sceneRadius * integral;
}

// The light-selection distribution (LightRecord.pmf): every delta light with probability 1, since it costs one
// shadow ray and no sampling (the slides' equation sums them all; drawing one of several point lights instead
// quadrupled the variance of the path-traced showcase for a sixth less time per sample); the other lights one at
// a time in proportion to power, through the inclusive cdf over them. Black lights are never picked (their
// records stay, so that indices hold): from the last light with power on, the cdf is exactly 1, so that rounding
// cannot leave a sliver of [0, 1) to a black light after it. With no power at all, nothing is picked.
void normalise(SceneLights& lights) {
  double total = 0.0;
  for (std::size_t i = lights.punctualCount; i < lights.records.size(); ++i) total += lights.powers[i];
  double running = 0.0;
  for (std::size_t i = 0; i < lights.records.size(); ++i) {
    gpu::LightRecord& record = lights.records[i];
    if (i < lights.punctualCount) {
      record.pmf = 1.0f;
      record.cdf = 0.0f;
      continue;
    }
    const double probability = total > 0.0 ? lights.powers[i] / total : 0.0;
    running += probability;
    record.pmf = float(probability);
    record.cdf = float(running);
  }
  for (std::size_t i = lights.records.size(); i-- > lights.punctualCount;) {
    lights.records[i].cdf = 1.0f;
    if (lights.powers[i] > 0.0) break;
  }
}

float boundingRadius(const Scene& scene) {
  const SceneBounds bounds = sceneBounds(scene);
  return 0.5f * glm::length(bounds.high - bounds.low);
}

}  // namespace

SceneLights sceneLights(const Scene& scene, const EnvironmentTables& environmentTables) {
  SceneLights lights;
  lights.sceneRadius = boundingRadius(scene);
  for (const Light& light : scene.lights) {
    lights.records.push_back(punctualRecord(light.record));
    lights.powers.push_back(0.0);  // not drawn by power (normalise)
  }
  lights.punctualCount = static_cast<std::uint32_t>(lights.records.size());
  for (const MeshInstance& instance : scene.instances) {
    std::uint32_t first = gpu::kNoLight;
    if (emits(scene, instance.material)) {
      first = static_cast<std::uint32_t>(lights.records.size());
      addTriangleLights(scene, instance, lights);
    }
    lights.instanceFirstLight.push_back(first);
  }
  bool anySphereEmits = false;
  for (const Sphere& sphere : scene.spheres) anySphereEmits |= emits(scene, sphere.material);
  if (anySphereEmits) {
    lights.sphereFirstLight = static_cast<std::uint32_t>(lights.records.size());
    addSphereLights(scene, lights);
  }
  // The tables say whether there is an image to sample (the scene may be the upload's geometry, without pixels).
  if (environmentTables.fMean > 0.0f) {
    lights.environmentLight = static_cast<std::uint32_t>(lights.records.size());
    gpu::LightRecord record{};
    record.kind = gpu::kLightEnvironment;
    lights.records.push_back(record);
    lights.powers.push_back(environmentPower(scene.environment, environmentTables, lights.sceneRadius));
  }
  normalise(lights);
  return lights;
}

std::uint32_t lightKindsOf(const Scene& scene) {
  std::uint32_t kinds = 0;
  for (const Light& light : scene.lights) kinds |= 1u << light.record.type;
  for (const MeshInstance& instance : scene.instances) {
    if (emits(scene, instance.material)) kinds |= 1u << gpu::kLightTriangle;
  }
  for (const Sphere& sphere : scene.spheres) {
    if (emits(scene, sphere.material)) kinds |= 1u << gpu::kLightSphere;
  }
  if (scene.environment.hasImage()) kinds |= 1u << gpu::kLightEnvironment;
  return kinds;
}

void updatePunctualLights(SceneLights& sceneLights, std::span<const Light> lights) {
  if (lights.size() != sceneLights.punctualCount) throw Error("updateLights: the light count changed");
  // Delta lights are selected with probability 1 whatever their power: the distribution stays.
  for (std::size_t i = 0; i < lights.size(); ++i) {
    sceneLights.records[i] = punctualRecord(lights[i].record);
    sceneLights.records[i].pmf = 1.0f;
  }
}

}  // namespace raylab
