#include "render/light_records.h"

#include <cmath>
#include <string>

#include "brdf_params/material_params.h"
#include "image/image.h"
#include "scene/camera_pivot.h"
#include "scene/texture_lookup.h"
#include "util/error.h"

namespace raylab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Sub-triangles per side when averaging an emissive texture over a triangle: from 16 lookups to 256.
constexpr int kMinEmissionSubdivisions = 4;
constexpr int kMaxEmissionSubdivisions = 16;

// A punctual light's record. Its kind must be a delta light's: the selection takes every one of them.
gpu::LightRecord punctualRecord(const PunctualLight& light) {
  gpu::LightRecord record{};
  record.kind = light.type;
  record.p0 = light.position;
  record.p1 = light.direction;
  record.p2 = glm::vec3(light.cosInner, light.cosOuter, 0.0f);
  record.radiance = light.intensity;
  record.texturedInstance = gpu::kNoInstance;
  if (light.type >= gpu::kLightKindCount || !(gpu::kDeltaLightKinds & (1u << light.type))) {
    throw Error("light kind " + std::to_string(light.type) + " is not a punctual light");
  }
  return record;
}

// Powers (SceneLights.powers) are in watts of luminance, so that lights of different kinds compare (pbrt-v4's
// Light::Phi). A one-sided Lambertian emitter of mean radiance L_e over its area A emits pi L_e A.
double surfacePower(glm::dvec3 meanRadiance, float area) {
  return kPi * double(luminance(glm::vec3(meanRadiance))) * double(area);
}

// The emissive texture a material's emission is multiplied by, or nullptr.
const gpu::TextureRef* emissiveTexture(const Scene& scene, const gpu::MaterialRecord& record) {
  if (record.textures < 0) return nullptr;
  const gpu::TextureRef& ref = scene.materialTextures[std::size_t(record.textures)].refs[gpu::kTextureEmissive];
  return ref.texture >= 0 ? &ref : nullptr;
}

// The mean of an emissive texture over triangle `first` (its first index) of `mesh`, linear RGB: the centroid rule
// on n x n congruent sub-triangles, n growing with the texels the triangle covers. Only the light-selection
// distribution uses it; L_e at each sampled point is the texture's (lights/triangle.glsl), so a rough mean costs
// variance, never bias.
glm::dvec3 meanEmissiveTexel(std::span<const Texture> textures, const gpu::TextureRef& ref, const Mesh& mesh,
                             std::size_t first) {
  const Texture& texture = textures[std::size_t(ref.texture)];
  glm::dvec2 uv[3];
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t v = mesh.indices[first + std::size_t(k)];
    const glm::dvec2 uv0 = mesh.uvs.empty() ? glm::dvec2(0.0) : glm::dvec2(mesh.uvs[v]);
    const glm::dvec2 uv1 = mesh.uvs1.empty() ? glm::dvec2(0.0) : glm::dvec2(mesh.uvs1[v]);
    uv[k] = textureUv(ref, uv0, uv1);  // affine: interpolating the transformed UVs is transforming the interpolated
  }
  const glm::dvec2 e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
  const double texels = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x) * texture.width * texture.height;
  // About two points across each texel the triangle spans, at least 4 x 4 (a triangle within one or two texels
  // can still straddle a texel edge).
  const double side = std::isfinite(texels) ? 2.0 * std::ceil(std::sqrt(texels)) : double(kMaxEmissionSubdivisions);
  const int n = int(std::clamp(side, double(kMinEmissionSubdivisions), double(kMaxEmissionSubdivisions)));
  glm::dvec3 sum(0.0);
  const auto add = [&](double b1, double b2) { sum += glm::dvec3(sampleTexture(texture, uv[0] + b1 * e1 + b2 * e2, true)); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      add((i + 1.0 / 3.0) / n, (j + 1.0 / 3.0) / n);                // the sub-triangle pointing like the triangle
      if (i + j + 1 < n) add((i + 2.0 / 3.0) / n, (j + 2.0 / 3.0) / n);  // the one pointing the other way
    }
  }
  return sum / double(n * n);
}

void addTriangleLights(const Scene& scene, const EmitterSurfaces& surfaces, std::size_t instanceIndex,
                       SceneLights& lights) {
  const MeshInstance& instance = scene.instances[instanceIndex];
  const Mesh& mesh = scene.meshes[instance.mesh];
  const gpu::MaterialRecord& material = scene.materials[instance.material].record;
  const gpu::TextureRef* texture = emissiveTexture(scene, material);
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    gpu::LightRecord record{};
    record.kind = gpu::kLightTriangle;
    record.p0 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i]], 1.0f));
    record.p1 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i + 1]], 1.0f));
    record.p2 = glm::vec3(instance.transform * glm::vec4(mesh.positions[mesh.indices[i + 2]], 1.0f));
    record.radiance = material.emission * opacityOf(material);  // next event sees the coverage, kernel/emission.glsl
    record.area = 0.5f * glm::length(glm::cross(record.p1 - record.p0, record.p2 - record.p0));
    record.texturedInstance = gpu::kNoInstance;
    record.primitive = static_cast<std::uint32_t>(i / 3);
    glm::dvec3 texelMean(1.0);
    if (texture != nullptr) {
      record.texturedInstance = surfaces.instanceRecords.at(instanceIndex);
      texelMean = meanEmissiveTexel(surfaces.textures, *texture, mesh, i);
    }
    lights.records.push_back(record);
    lights.powers.push_back(surfacePower(glm::dvec3(record.radiance) * texelMean, record.area));
    lights.materials.push_back(instance.material);
    lights.texelMeans.push_back(texelMean);
  }
}

// The mean of an emissive texture over a sphere, linear RGB: its UVs are longitude and colatitude
// (kernel/surface.glsl, sphereSurface), so texels near the poles weigh sin(colatitude) less.
glm::dvec3 meanEmissiveTexelOnSphere(std::span<const Texture> textures, const gpu::TextureRef& ref) {
  const Texture& texture = textures[std::size_t(ref.texture)];
  constexpr int kColumns = 2 * kMaxEmissionSubdivisions, kRows = kMaxEmissionSubdivisions;
  glm::dvec3 sum(0.0);
  double weights = 0.0;
  for (int row = 0; row < kRows; ++row) {
    const double v = (row + 0.5) / kRows;
    const double weight = std::sin(kPi * v);
    for (int column = 0; column < kColumns; ++column) {
      const glm::dvec2 uv((column + 0.5) / kColumns, v);
      sum += weight * glm::dvec3(sampleTexture(texture, textureUv(ref, uv, uv), true));
      weights += weight;
    }
  }
  return sum / weights;
}

// One record per sphere (power 0 for those that do not emit), so that record = sphereFirstLight + primitive.
void addSphereLights(const Scene& scene, const EmitterSurfaces& surfaces, SceneLights& lights) {
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& sphere = scene.spheres[i];
    const gpu::MaterialRecord& material = scene.materials[sphere.material].record;
    gpu::LightRecord record{};
    record.kind = gpu::kLightSphere;
    record.p0 = sphere.center;
    record.p1 = glm::vec3(sphere.radius, 0.0f, 0.0f);
    record.radiance = material.emission * opacityOf(material);  // next event sees the coverage, kernel/emission.glsl
    record.area = float(4.0 * kPi * double(sphere.radius) * sphere.radius);
    record.texturedInstance = gpu::kNoInstance;
    record.primitive = static_cast<std::uint32_t>(i);
    glm::dvec3 texelMean(1.0);
    if (const gpu::TextureRef* texture = emissiveTexture(scene, material)) {
      record.texturedInstance = surfaces.sphereInstanceRecord;
      texelMean = meanEmissiveTexelOnSphere(surfaces.textures, *texture);
    }
    lights.records.push_back(record);
    lights.powers.push_back(surfacePower(glm::dvec3(record.radiance) * texelMean, record.area));
    lights.materials.push_back(sphere.material);
    lights.texelMeans.push_back(texelMean);
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

SceneLights sceneLights(const Scene& scene, const EnvironmentTables& environmentTables,
                        const EmitterSurfaces& surfaces) {
  SceneLights lights;
  lights.sceneRadius = boundingRadius(scene);
  for (const Light& light : scene.lights) {
    lights.records.push_back(punctualRecord(light.record));
    lights.powers.push_back(0.0);  // not drawn by power (normalise)
    lights.materials.push_back(kNoEmitterMaterial);
    lights.texelMeans.push_back(glm::dvec3(1.0));
  }
  lights.punctualCount = static_cast<std::uint32_t>(lights.records.size());
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& instance = scene.instances[i];
    std::uint32_t first = gpu::kNoLight;
    if (emits(scene, instance.material)) {
      first = static_cast<std::uint32_t>(lights.records.size());
      addTriangleLights(scene, surfaces, i, lights);
    } else {
      lights.materialsWithoutRecords.push_back(instance.material);
    }
    lights.instanceFirstLight.push_back(first);
  }
  bool anySphereEmits = false;
  for (const Sphere& sphere : scene.spheres) anySphereEmits |= emits(scene, sphere.material);
  if (anySphereEmits) {
    lights.sphereFirstLight = static_cast<std::uint32_t>(lights.records.size());
    addSphereLights(scene, surfaces, lights);
  } else {
    for (const Sphere& sphere : scene.spheres) lights.materialsWithoutRecords.push_back(sphere.material);
  }
  // The tables say whether there is an image to sample (the scene may be the upload's geometry, without pixels).
  if (environmentTables.fMean > 0.0f) {
    lights.environmentLight = static_cast<std::uint32_t>(lights.records.size());
    gpu::LightRecord record{};
    record.kind = gpu::kLightEnvironment;
    record.texturedInstance = gpu::kNoInstance;
    lights.records.push_back(record);
    lights.powers.push_back(environmentPower(scene.environment, environmentTables, lights.sceneRadius));
    lights.materials.push_back(kNoEmitterMaterial);
    lights.texelMeans.push_back(glm::dvec3(1.0));
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

bool updateEmitters(SceneLights& sceneLights, std::span<const Material> materials) {
  for (std::size_t i = 0; i < sceneLights.records.size(); ++i) {
    const std::uint32_t material = sceneLights.materials[i];
    if (material == kNoEmitterMaterial) continue;
    const gpu::MaterialRecord& record = materials[material].record;
    gpu::LightRecord& light = sceneLights.records[i];
    light.radiance = record.emission * opacityOf(record);  // as addTriangleLights and addSphereLights make it
    sceneLights.powers[i] = surfacePower(glm::dvec3(light.radiance) * sceneLights.texelMeans[i], light.area);
  }
  normalise(sceneLights);
  for (const std::uint32_t material : sceneLights.materialsWithoutRecords) {
    const glm::vec3 e = materials[material].record.emission;
    if (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f) return false;
  }
  return true;
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
