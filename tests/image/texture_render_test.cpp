// Material textures in whole renders, against what their texels say: a normal map tilts the Lambert shading to
// the closed form of the mapped normal, a metallic-roughness texture renders as its factors scaled by the texel,
// a use's UV set and KHR_texture_transform choose the texel, an alpha mask cuts holes that rays and shadows pass
// through, and a blended surface is seen in proportion to its alpha. Every scene's first render is also checked
// bit for bit on the other backend (renderImage). The integrators share applyTextures and the traversal, so each
// test runs one of them: kernel variants are what this test's time goes to.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "brdf_params/material_params.h"
#include "render/kernel_features.h"
#include "scene/tangents.h"
#include "scene/texture_lookup.h"
#include "shared/features.h"
#include "support/analytic.h"
#include "support/gpu_test.h"
#include "texture_scenes.h"

namespace raylab::test {
namespace {

class TextureRenderTest : public GpuTest {};

constexpr double kRho = 0.5;
const glm::dvec3 kLight{2.0, 3.0, 0.5};
constexpr double kIntensity = 10.0;

// The quad under a point light, seen from above, with `record` and one texture in use `slot`.
Scene quadScene(const gpu::MaterialRecord& record, std::uint32_t slot, const Texture& texture, const Mesh& mesh) {
  Scene scene;
  scene.name = "textured quad";
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.textures.push_back(texture);
  gpu::MaterialTextures uses = noMaterialTextures();
  uses.refs[slot] = textureRef(0);
  scene.materialTextures.push_back(uses);
  scene.materials.push_back({"textured", record});
  scene.materials[0].record.textures = 0;
  scene.lights.push_back({"lamp", pointLight(glm::vec3(kLight), glm::vec3(float(kIntensity)))});
  scene.camera.position = {0.0f, 4.0f, 0.01f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(20.0f);
  return scene;
}

RenderSettings settingsFor(const Scene& scene, std::uint32_t integrator) {
  RenderSettings settings = pixelCentres(48, 48);
  KernelFeatures kernel = featuresOf(scene);
  kernel.integrator = integrator;
  settings.kernel = kernel;
  settings.maxDepth = 0;  // direct light only in both integrators: the closed form below
  return settings;
}

// For every pixel whose centre ray hits the quad: rho/pi I max(0, ns.l) / r^2 with the normal the texel encodes
// in the quad's frame (tangent +x, bitangent +z, normal +y), reversed on the back face (`back`, glTF 3.9.5:
// a double-sided material's back face has its normals reversed). Returns how many pixels were compared.
int expectMappedLambert(const Image& image, const gpu::FrameParams& params, glm::dvec3 mapped,
                        glm::dvec3 light = kLight, bool back = false) {
  const glm::dvec3 front = glm::normalize(mapped.x * glm::dvec3(1, 0, 0) + mapped.y * glm::dvec3(0, 0, 1) +
                                          mapped.z * glm::dvec3(0, 1, 0));
  const glm::dvec3 ns = back ? -front : front;
  int compared = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      const double t = -ray.origin.y / ray.direction.y;
      const glm::dvec3 p = ray.origin + t * ray.direction;
      if (std::abs(p.x) > 0.98 || std::abs(p.z) > 0.98) continue;  // off the quad, or at its edge
      // No bend: the kernel bends a mapped normal towards ng only for BSDFs that reflect about it
      // (validReflectionNormal, kernel/hit_common.glsl), and Lambert does not.
      const glm::dvec3 toLight = light - p;
      const double r2 = glm::dot(toLight, toLight);
      const double expected = kRho / kPi * kIntensity * std::max(0.0, glm::dot(ns, toLight) / std::sqrt(r2)) / r2;
      EXPECT_NEAR(image.at(x, y).r, expected, 2e-4 * expected + 1e-6) << "pixel " << x << "," << y;
      ++compared;
    }
  }
  return compared;
}

TEST_F(TextureRenderTest, ANormalMapShadesAsTheNormalItsTexelEncodes) {
  // Texels tilting the normal towards +u (the light's side), towards -v, the flat (128, 128, 255), and 60 degrees
  // towards +u: the mirror direction of the view (from above) about it lies under the surface, and a bend for it
  // used to shade the Lambertian quad as a normal tilted 45 degrees (10% brighter here).
  const std::uint8_t texels[][3] = {{200, 128, 230}, {128, 60, 240}, {128, 128, 255}, {238, 128, 191}};
  Mesh mesh = texturedQuad();
  mesh.tangents = generateTangents(mesh, mesh.uvs);
  for (const glm::vec4& t : mesh.tangents) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f) << "the tangent follows +u";
    EXPECT_EQ(t.w, -1.0f) << "cross(n, t) is -z, so w = -1 turns the bitangent to +z, along +v";
  }
  for (const auto& texel : texels) {
    const Scene scene = quadScene(lambertMaterial(glm::vec3(float(kRho))), gpu::kTextureNormal,
                                  solidTexture({texel[0], texel[1], texel[2], 255}), mesh);
    // Lavapipe's unpackUnorm4x8 is byte / 255.
    const glm::dvec3 mapped = glm::dvec3(texel[0], texel[1], texel[2]) / 255.0 * 2.0 - 1.0;
    // The normal-map texel as the slides' integrator shades it; the path integrator shades through the same
    // applyTextures and shadingSide (kernel/hit_common.glsl), and runs in the next test.
    const Image image = renderImage(device(), scene, settingsFor(scene, gpu::kIntegratorSlides), 1);
    EXPECT_GT(expectMappedLambert(image, frameFor(scene, 48, 48), mapped), 1000);
  }
}

// Every material is double-sided (docs/scenes.md, Normal maps): seen from below, with the light below, the quad's
// back face shades as the mapped normal reversed, tangent frame and all, as glTF says of double-sided materials.
TEST_F(TextureRenderTest, TheBackFaceShadesAsTheMappedNormalReversed) {
  Mesh mesh = texturedQuad();
  mesh.tangents = generateTangents(mesh, mesh.uvs);
  const std::uint8_t texel[3] = {200, 90, 230};
  Scene scene = quadScene(lambertMaterial(glm::vec3(float(kRho))), gpu::kTextureNormal,
                          solidTexture({texel[0], texel[1], texel[2], 255}), mesh);
  const glm::dvec3 below(-2.0, -3.0, 0.5);
  scene.lights[0].record = pointLight(glm::vec3(below), glm::vec3(float(kIntensity)));
  scene.camera.position = {0.0f, -4.0f, 0.01f};
  const glm::dvec3 mapped = glm::dvec3(texel[0], texel[1], texel[2]) / 255.0 * 2.0 - 1.0;
  const Image image = renderImage(device(), scene, settingsFor(scene, gpu::kIntegratorSlides), 1);
  EXPECT_GT(expectMappedLambert(image, frameFor(scene, 48, 48), mapped, below, true), 1000);
}

// A normal map whose texel points far below the horizon never leaves the shading normal under the surface: the
// quad still renders finite, non-negative radiance, and lit where the clamped normal faces the light.
TEST_F(TextureRenderTest, ANormalMapPointingIntoTheSurfaceIsClampedAboveIt) {
  Mesh mesh = texturedQuad();
  mesh.tangents = generateTangents(mesh, mesh.uvs);
  const Scene scene = quadScene(lambertMaterial(glm::vec3(float(kRho))), gpu::kTextureNormal,
                                solidTexture({255, 128, 0, 255}), mesh);  // (1, 0, -1): 45 degrees under
  const Image image = renderImage(device(), scene, settingsFor(scene, gpu::kIntegratorSlides), 1);
  double sum = 0.0;
  for (const float value : image.rgba) {
    ASSERT_TRUE(std::isfinite(value) && value >= 0.0f);
    sum += value;
  }
  EXPECT_GT(sum, 0.0) << "the clamped normal still sees the light on the +x side";
}

TEST_F(TextureRenderTest, AMetallicRoughnessTextureScalesTheFactorsByItsGreenAndBlue) {
  gpu::MaterialRecord record = defaultRecord(modelId("gltf_pbr"));
  setParam(record, "base_color", glm::vec3(0.9f, 0.6f, 0.3f), "test");
  setParam(record, "metallic", glm::vec3(0.8f), "test");
  setParam(record, "roughness", glm::vec3(0.9f), "test");
  const std::uint8_t green = 90, blue = 200;
  const Scene textured = quadScene(record, gpu::kTextureMetallicRoughness, solidTexture({17, green, blue, 255}),
                                   texturedQuad());
  // The same kernel variant (textures on) with a white texel and the factors scaled on the host.
  Scene plain = textured;
  plain.textures[0].rgba = {17, 255, 255, 255};
  setParam(plain.materials[0].record, "roughness", glm::vec3(0.9f * float(green) / 255.0f), "test");
  setParam(plain.materials[0].record, "metallic", glm::vec3(0.8f * float(blue) / 255.0f), "test");
  // Both integrators apply textures in one function (kernel/hit_common.glsl); the normal map test runs both.
  for (const std::uint32_t integrator : {gpu::kIntegratorPath}) {
    const Image a = renderImage(device(), textured, settingsFor(textured, integrator), 1);
    const Image b = renderImage(device(), plain, settingsFor(plain, integrator), 1);
    int lit = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
      EXPECT_NEAR(a.rgba[i], b.rgba[i], 1e-5f * b.rgba[i] + 1e-7f) << "value " << i;
      lit += i % 4 == 0 && b.rgba[i] > 0.0f;
    }
    EXPECT_GT(lit, 1000);
  }
}

// `textured` (textures on its material) renders as `plain`, the same scene with white texels and its parameters
// scaled on the host, to 2e-5 relative, on the slides integrator; and the textures matter: the white texels with the
// parameters unscaled render differently.
// a and b agree value by value (float32 on the device: 1e-4 relative); returns how far a is from `other`, as a share
// of other's total: that the change under test shows at all.
double agreeAndDiffer(const Image& a, const Image& b, const Image& other) {
  double difference = 0.0, total = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (!(std::abs(a.rgba[i] - b.rgba[i]) <= 1e-4f * b.rgba[i] + 1e-7f)) {
      ADD_FAILURE() << "value " << i << ": " << a.rgba[i] << " against " << b.rgba[i];
      return 0.0;
    }
    difference += std::abs(a.rgba[i] - other.rgba[i]);
    total += other.rgba[i];
  }
  return difference / total;
}

void expectTexturesActAsHostScaling(const Device& device, const Scene& textured, const Scene& plain) {
  const RenderSettings settings = settingsFor(textured, gpu::kIntegratorSlides);  // one kernel variant for all three
  const Image a = renderImage(device, textured, settings, 1);
  const Image b = renderImage(device, plain, settings, 1);
  int lit = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    EXPECT_NEAR(a.rgba[i], b.rgba[i], 2e-5f * b.rgba[i] + 1e-7f) << "value " << i;
    lit += i % 4 == 0 && b.rgba[i] > 0.0f;
  }
  EXPECT_GT(lit, 1000);
  Scene unscaled = textured;
  for (Texture& texture : unscaled.textures) std::fill(texture.rgba.begin(), texture.rgba.end(), std::uint8_t(255));
  const Image c = renderImage(device, unscaled, settings, 1);
  double difference = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) difference += std::abs(double(a.rgba[i]) - double(c.rgba[i]));
  EXPECT_GT(difference, 1.0);
}

// KHR_materials_specular's textures: A scales `specular`, the sRGB-decoded RGB `specular_color`; the same render
// as white texels with the parameters scaled on the host.
TEST_F(TextureRenderTest, SpecularTexturesScaleTheDielectricsStrengthAndColour) {
  gpu::MaterialRecord record = defaultRecord(modelId("gltf_pbr"));
  setParam(record, "base_color", glm::vec3(0.3f, 0.5f, 0.7f), "test");
  setParam(record, "roughness", glm::vec3(0.3f), "test");
  setParam(record, "specular_color", glm::vec3(4.0f, 2.0f, 1.0f), "test");
  const std::uint8_t texel[4] = {200, 100, 50, 90};
  Scene textured = quadScene(record, gpu::kTextureSpecular, solidTexture({texel[0], texel[1], texel[2], texel[3]}),
                             texturedQuad());
  textured.materialTextures[0].refs[gpu::kTextureSpecularColor] = textureRef(0);
  Scene plain = textured;
  plain.textures[0].rgba = {255, 255, 255, 255};
  setParam(plain.materials[0].record, "specular", glm::vec3(float(texel[3]) / 255.0f), "test");
  const glm::vec3 tint(srgbToLinear(texel[0] / 255.0), srgbToLinear(texel[1] / 255.0), srgbToLinear(texel[2] / 255.0));
  setParam(plain.materials[0].record, "specular_color", glm::vec3(4.0f, 2.0f, 1.0f) * tint, "test");
  expectTexturesActAsHostScaling(device(), textured, plain);
}

// The layered extensions' textures (glTF's clearcoat, sheen, iridescence, transmission and the coat, fuzz and diffuse
// roughness drafts on openpbr): each scales its parameter by its channel, R the weights and the diffuse roughness, G
// the coat's roughness and the film's thickness (from the floor minimum / maximum up), A the fuzz's roughness, the sRGB
// RGB the fuzz's and the coat's colours; the same render as white texels with the parameters scaled on the host. On another model (a material switched away in the viewer) they read nothing.
TEST_F(TextureRenderTest, LayerTexturesScaleTheLayersParameters) {
  gpu::MaterialRecord record = defaultRecord(modelId("openpbr"));
  const std::vector<std::pair<const char*, float>> layers = {
      {"coat_weight", 0.9f}, {"coat_roughness", 0.4f}, {"fuzz_weight", 0.8f}, {"fuzz_roughness", 0.6f},
      {"thin_film_weight", 0.7f}, {"thin_film_thickness", 0.5f}, {"transmission_weight", 0.6f}};
  for (const auto& [name, value] : layers) setParam(record, name, glm::vec3(value), "test");
  setParam(record, "fuzz_color", glm::vec3(1.0f, 0.8f, 0.6f), "test");
  setParam(record, "coat_color", glm::vec3(0.9f, 0.7f, 1.0f), "test");
  setParam(record, "base_diffuse_roughness", glm::vec3(0.5f), "test");
  setParam(record, "subsurface_weight", glm::vec3(0.7f), "test");
  setParam(record, "subsurface_color", glm::vec3(0.6f, 0.8f, 0.4f), "test");
  const std::uint8_t texel[4] = {200, 100, 50, 90};
  constexpr float kThicknessFloor = 0.25f;
  Scene textured = quadScene(record, gpu::kTextureCoat, solidTexture({texel[0], texel[1], texel[2], texel[3]}),
                             texturedQuad());
  gpu::MaterialTextures& uses = textured.materialTextures[0];
  const auto layer = [&](std::uint32_t use, const char* param) {
    uses.refs[use] = textureRef(0);
    uses.refs[use].param = findParam(modelInfo(record.model), param)->slot;
    uses.refs[use].scale = use == gpu::kTextureIridescenceThickness ? kThicknessFloor : 0.0f;
  };
  layer(gpu::kTextureCoat, "coat_weight");
  layer(gpu::kTextureCoatRoughness, "coat_roughness");
  layer(gpu::kTextureSheenColor, "fuzz_color");
  layer(gpu::kTextureSheenRoughness, "fuzz_roughness");
  layer(gpu::kTextureIridescence, "thin_film_weight");
  layer(gpu::kTextureIridescenceThickness, "thin_film_thickness");
  layer(gpu::kTextureTransmission, "transmission_weight");
  layer(gpu::kTextureCoatColor, "coat_color");
  layer(gpu::kTextureFuzz, "fuzz_weight");
  layer(gpu::kTextureDiffuseRoughness, "base_diffuse_roughness");
  layer(gpu::kTextureDiffuseTransmission, "subsurface_weight");
  layer(gpu::kTextureDiffuseTransmissionColor, "subsurface_color");
  uses.layerModel = record.model;
  ASSERT_TRUE(hasLayerTextures(textured, textured.materials[0].record));
  ASSERT_NE(featuresOf(textured).features & gpu::kFeatureLayerTextures, 0u);
  Scene plain = textured;
  plain.textures[0].rgba = {255, 255, 255, 255};
  gpu::MaterialRecord& scaled = plain.materials[0].record;
  const float r = texel[0] / 255.0f, g = texel[1] / 255.0f, a = texel[3] / 255.0f;
  setParam(scaled, "coat_weight", glm::vec3(0.9f * r), "test");
  setParam(scaled, "coat_roughness", glm::vec3(0.4f * g), "test");
  setParam(scaled, "fuzz_roughness", glm::vec3(0.6f * a), "test");
  setParam(scaled, "thin_film_weight", glm::vec3(0.7f * r), "test");
  setParam(scaled, "thin_film_thickness", glm::vec3(0.5f * (kThicknessFloor + (1.0f - kThicknessFloor) * g)), "test");
  setParam(scaled, "transmission_weight", glm::vec3(0.6f * r), "test");
  setParam(scaled, "fuzz_weight", glm::vec3(0.8f * r), "test");
  setParam(scaled, "base_diffuse_roughness", glm::vec3(0.5f * r), "test");
  setParam(scaled, "subsurface_weight", glm::vec3(0.7f * a), "test");
  const glm::vec3 tint(srgbToLinear(texel[0] / 255.0), srgbToLinear(texel[1] / 255.0), srgbToLinear(texel[2] / 255.0));
  setParam(scaled, "fuzz_color", glm::vec3(1.0f, 0.8f, 0.6f) * tint, "test");
  setParam(scaled, "coat_color", glm::vec3(0.9f, 0.7f, 1.0f) * tint, "test");
  setParam(scaled, "subsurface_color", glm::vec3(0.6f, 0.8f, 0.4f) * tint, "test");
  expectTexturesActAsHostScaling(device(), textured, plain);
  // For another model (a material switched away in the viewer) they read nothing.
  Scene switched = textured;
  switched.materialTextures[0].layerModel = modelId("gltf_pbr");
  EXPECT_FALSE(hasLayerTextures(switched, switched.materials[0].record));
}

// KHR_materials_anisotropy's direction: the anisotropic base turned by anisotropyRotation = pi/4, from the tangent
// (+u, along +x) towards the bitangent (+v, along +z), renders as the unturned material on a quad whose u runs along
// x + z (turned the other way, along x - z, it would not: the light is off the diagonal); and the texture's RG
// direction and B strength render as that angle and the strength's ratio set on the host.
TEST_F(TextureRenderTest, TheAnisotropysRotationAndTextureTurnAndScaleTheStretch) {
  gpu::MaterialRecord record = defaultRecord(modelId("openpbr"));
  setParam(record, "base_metalness", glm::vec3(1.0f), "test");
  setParam(record, "base_color", glm::vec3(0.9f, 0.7f, 0.5f), "test");
  setParam(record, "specular_roughness", glm::vec3(0.45f), "test");
  setParam(record, "specular_roughness_anisotropy", glm::vec3(0.85f), "test");
  // Under a faint anisotropic coat turned half a turn in its own frame (which shows nothing: the stretch is along an
  // axis): the kernel of the coat normal map's test below, coat frame included (one cold compile of the layered
  // kernel for both, not two: over a minute each).
  setParam(record, "coat_weight", glm::vec3(0.2f), "test");
  setParam(record, "coat_roughness", glm::vec3(0.3f), "test");
  setParam(record, "coat_roughness_anisotropy", glm::vec3(0.6f), "test");
  setParam(record, "geometry_coat_tangent_angle", glm::vec3(float(std::numbers::pi)), "test");
  const auto sceneOf = [&](const Mesh& mesh, float rotation) {
    Scene scene = quadScene(record, gpu::kTextureBaseColor, solidTexture({255, 255, 255, 255}), mesh);
    scene.materialTextures[0].anisotropyRotation = rotation;
    scene.materialTextures[0].layerModel = record.model;
    return scene;
  };
  Mesh turnedUvs = texturedQuad();
  turnedUvs.uvs = {{0, 0.5f}, {0.5f, 0}, {1, 0.5f}, {0.5f, 1}};  // u' = (u + v) / 2: dp/du' along x + z
  const Scene turned = sceneOf(texturedQuad(), float(std::numbers::pi / 4.0));
  ASSERT_NE(featuresOf(turned).features & gpu::kFeatureLayerTextures, 0u) << "a rotation alone needs the feature";
  const auto render = [&](const Scene& scene) {
    return renderImage(device(), scene, settingsFor(scene, gpu::kIntegratorSlides), 1);
  };
  // A whole turn is no turn, rendered by the same kernel as the turned scene (the rotation feature on): one kernel
  // to compile for the test, not two.
  const float whole = float(2.0 * std::numbers::pi);
  const Image a = render(turned);
  const Image b = render(sceneOf(turnedUvs, whole));
  const Image unturned = render(sceneOf(texturedQuad(), whole));
  EXPECT_GT(agreeAndDiffer(a, b, unturned), 0.05) << "the turn shows: the stretch is not along the first tangent any more";

  // The texture: RG (0, 128) is the direction (-1, 1/255), B 170 two thirds of the strength 0.6.
  const std::uint8_t texel[4] = {0, 128, 170, 255};
  Scene textured = sceneOf(texturedQuad(), 0.3f);
  textured.textures[0] = solidTexture({texel[0], texel[1], texel[2], texel[3]});
  textured.materialTextures[0].refs[gpu::kTextureBaseColor] = noTextureRef();
  textured.materialTextures[0].refs[gpu::kTextureAnisotropy] = textureRef(0);
  textured.materialTextures[0].refs[gpu::kTextureAnisotropy].param =
      findParam(modelInfo(record.model), "specular_roughness_anisotropy")->slot;
  textured.materialTextures[0].refs[gpu::kTextureAnisotropy].scale = 0.6f;
  const double strength = 0.6 * texel[2] / 255.0, alpha = 0.45 * 0.45;
  Scene host = sceneOf(texturedQuad(), float(0.3 + std::atan2(2.0 * texel[1] / 255.0 - 1.0, 2.0 * texel[0] / 255.0 - 1.0)));
  setParam(host.materials[0].record, "specular_roughness_anisotropy",
           glm::vec3(float(1.0 - alpha / (alpha + (1.0 - alpha) * strength * strength))), "test");
  const Image t = render(textured);
  const Image h = render(host);
  for (std::size_t i = 0; i < t.rgba.size(); ++i) ASSERT_NEAR(t.rgba[i], h.rgba[i], 1e-4f * h.rgba[i] + 1e-7f) << i;

  // KHR_materials_coat's anisotropy texture beside the base's: the coat's texel turns the coat by its direction and
  // scales its strength 0.8 by its B, and the coat's angle loses the base texel's turn, which the frame already
  // carries. Directions off the axes, so that a turn of the wrong size shows.
  const std::uint8_t baseTexel[4] = {200, 230, 170, 255}, coatTexel[4] = {230, 60, 128, 255};
  const auto turnOf = [](const std::uint8_t* c) { return std::atan2(2.0 * c[1] / 255.0 - 1.0, 2.0 * c[0] / 255.0 - 1.0); };
  const auto ratioOf = [](double strength, double roughness) {
    const double a = roughness * roughness;
    return float(1.0 - a / (a + (1.0 - a) * strength * strength));
  };
  Scene coated = textured;
  coated.textures[0] = solidTexture({baseTexel[0], baseTexel[1], baseTexel[2], baseTexel[3]});
  coated.textures.push_back(solidTexture({coatTexel[0], coatTexel[1], coatTexel[2], coatTexel[3]}));
  gpu::TextureRef& coatRef = coated.materialTextures[0].refs[gpu::kTextureCoatAnisotropy];
  coatRef = textureRef(1);
  const ModelInfo& openpbr = modelInfo(record.model);
  coatRef.param = findParam(openpbr, "coat_roughness_anisotropy")->slot | findParam(openpbr, "coat_roughness")->slot << 8u |
                  findParam(openpbr, "geometry_coat_tangent_angle")->slot << 16u;
  coatRef.scale = 0.8f;
  const auto hostCoated = [&](double coatTurn) {
    Scene scene = sceneOf(texturedQuad(), float(0.3 + turnOf(baseTexel)));
    gpu::MaterialRecord& r = scene.materials[0].record;
    setParam(r, "specular_roughness_anisotropy", glm::vec3(ratioOf(0.6 * baseTexel[2] / 255.0, 0.45)), "test");
    setParam(r, "coat_roughness_anisotropy", glm::vec3(ratioOf(0.8 * coatTexel[2] / 255.0, 0.3)), "test");
    setParam(r, "geometry_coat_tangent_angle", glm::vec3(float(std::numbers::pi + coatTurn)), "test");
    return scene;
  };
  const Image tc = render(coated);
  const Image hc = render(hostCoated(turnOf(coatTexel) - turnOf(baseTexel)));
  const Image unsubtracted = render(hostCoated(turnOf(coatTexel)));
  EXPECT_GT(agreeAndDiffer(tc, hc, unsubtracted), 1e-3) << "the coat's turn shows";
}

// The coat's own normal map (glTF's coatNormalTexture, clearcoatNormalTexture): decoded in the quad's tangent frame
// (tangent +x, bitangent +z, normal +y: the base's normal map's) and given to the coat in the shading frame (x the
// tangent, y cross(n, t) = -z), it renders as that normal set on the host as geometry_coat_normal_x and _y.
TEST_F(TextureRenderTest, ACoatNormalMapTiltsTheCoatAsItsTexelEncodes) {
  gpu::MaterialRecord record = defaultRecord(modelId("openpbr"));
  setParam(record, "base_color", glm::vec3(0.3f, 0.2f, 0.1f), "test");
  setParam(record, "specular_roughness", glm::vec3(0.5f), "test");
  setParam(record, "coat_weight", glm::vec3(1.0f), "test");
  setParam(record, "coat_roughness", glm::vec3(0.25f), "test");
  Mesh mesh = texturedQuad();
  mesh.tangents = generateTangents(mesh, mesh.uvs);
  // The layer textures' kernel for all three (a whole turn of the anisotropy's direction is none), shared with the
  // anisotropy's test above.
  const auto sceneOf = [&](const gpu::MaterialRecord& r) {
    Scene scene = quadScene(r, gpu::kTextureBaseColor, solidTexture({255, 255, 255, 255}), mesh);
    scene.materialTextures[0].layerModel = r.model;
    scene.materialTextures[0].anisotropyRotation = float(2.0 * std::numbers::pi);
    return scene;
  };
  const std::uint8_t texel[3] = {200, 90, 220};
  Scene textured = sceneOf(record);
  textured.materialTextures[0].anisotropyRotation = 0.0f;
  textured.textures.push_back(solidTexture({texel[0], texel[1], texel[2], 255}));
  textured.materialTextures[0].refs[gpu::kTextureCoatNormal] = textureRef(1);
  textured.materialTextures[0].refs[gpu::kTextureCoatNormal].param =
      findParam(modelInfo(record.model), "geometry_coat_normal_x")->slot;
  ASSERT_NE(featuresOf(textured).features & gpu::kFeatureLayerTextures, 0u);
  const glm::dvec3 m = glm::normalize(glm::dvec3(texel[0], texel[1], texel[2]) / 255.0 * 2.0 - 1.0);
  gpu::MaterialRecord tilted = record;
  setParam(tilted, "geometry_coat_normal_x", glm::vec3(float(m.x)), "test");
  setParam(tilted, "geometry_coat_normal_y", glm::vec3(float(-m.y)), "test");
  const auto render = [&](const Scene& scene) {
    return renderImage(device(), scene, settingsFor(scene, gpu::kIntegratorSlides), 1);
  };
  // The untilted coat for comparison, turned half a turn so that its kernel has the coat frame too (an isotropic
  // coat's tangent shows nothing).
  gpu::MaterialRecord untilted = record;
  setParam(untilted, "geometry_coat_tangent_angle", glm::vec3(float(std::numbers::pi)), "test");
  const Image t = render(textured);
  const Image h = render(sceneOf(tilted));
  const Image flat = render(sceneOf(untilted));
  EXPECT_GT(agreeAndDiffer(t, h, flat), 0.01) << "the tilt shows: the coat's highlight moved";
}

// A 2x1 texture, red then green, read by the nearest texel: TEXCOORD_1 constant at u = 0.25 reads red, and a
// KHR_texture_transform offset of 0.5 moves it to green; on TEXCOORD_0 the quad's halves show one each.
TEST_F(TextureRenderTest, TheUvSetAndTheTransformChooseTheTexel) {
  Mesh mesh = texturedQuad();
  mesh.uvs1.assign(4, glm::vec2(0.25f, 0.5f));
  Texture texture = solidTexture({255, 0, 0, 255, 0, 255, 0, 255}, 2, 1);
  texture.nearest = true;
  Scene scene = quadScene(lambertMaterial(glm::vec3(1.0f)), gpu::kTextureBaseColor, texture, mesh);
  const auto colours = [&](const Scene& s) {
    const Image image = renderImage(device(), s, settingsFor(s, gpu::kIntegratorSlides), 1);
    int red = 0, green = 0;
    for (std::uint32_t y = 0; y < image.height; ++y) {
      for (std::uint32_t x = 0; x < image.width; ++x) {
        const glm::vec4 pixel = image.at(x, y);
        if (pixel.r > 0.0f && pixel.g == 0.0f) ++red;
        if (pixel.g > 0.0f && pixel.r == 0.0f) ++green;
      }
    }
    return std::pair{red, green};
  };
  scene.materialTextures[0].refs[gpu::kTextureBaseColor].texCoord = 1;
  auto [red, green] = colours(scene);
  EXPECT_GT(red, 1000);
  EXPECT_EQ(green, 0);
  scene.materialTextures[0].refs[gpu::kTextureBaseColor].row0.z = 0.5f;
  std::tie(red, green) = colours(scene);
  EXPECT_EQ(red, 0);
  EXPECT_GT(green, 1000);
  scene.materialTextures[0].refs[gpu::kTextureBaseColor] = textureRef(0);
  std::tie(red, green) = colours(scene);
  EXPECT_GT(red, 400);
  EXPECT_GT(green, 400);
}

// A 4x4 checker of alpha 0 and 255, read by the nearest texel.
Texture alphaChecker() {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const bool solid = (x + y) % 2 == 0;
      rgba.insert(rgba.end(), {255, 255, 255, std::uint8_t(solid ? 255 : 0)});
    }
  }
  Texture texture = solidTexture(rgba, 4, 4);
  texture.nearest = true;
  return texture;
}

// A white quad with `texture` as its base colour at y = 1 over a red floor three times its size at y = 0.
Scene quadOverRedFloor(const Texture& texture) {
  Scene scene = quadScene(lambertMaterial(glm::vec3(1.0f)), gpu::kTextureBaseColor, texture, texturedQuad());
  scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  Mesh floor = texturedQuad();
  for (glm::vec3& p : floor.positions) p *= glm::vec3(3.0f, 1.0f, 3.0f);
  scene.meshes.push_back(floor);
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(1.0f, 0.0f, 0.0f))});
  scene.instances.push_back({1, glm::mat4(1.0f), 1});
  return scene;
}

// An alpha-masked quad (white where the checker is solid) at y = 1 over a red floor at y = 0, seen from above
// and lit from straight above: the floor shows through exactly the quad's holes, and the quad's shadow on the
// floor is the checker, so the floor is lit only under the holes.
TEST_F(TextureRenderTest, AnAlphaMaskCutsHolesThatRaysAndShadowsPassThrough) {
  Scene scene = quadOverRedFloor(alphaChecker());
  scene.materialTextures[0].alphaMode = gpu::kAlphaMask;
  scene.materialTextures[0].alphaCutoff = 0.5f;
  scene.lights[0].record = pointLight(glm::vec3(0.0f, 50.0f, 0.0f), glm::vec3(2500.0f));
  scene.camera.position = {0.0f, 8.0f, 0.001f};
  scene.camera.yfov = glm::radians(20.0f);
  const std::uint32_t size = 64;
  // Both integrators trace through the same traversal (kernel/trace_query.glsl, or alpha.rahit): the path one
  // here, and in the next test.
  for (const std::uint32_t integrator : {gpu::kIntegratorPath}) {
    RenderSettings settings = settingsFor(scene, integrator);
    settings.width = settings.height = size;
    const Image image = renderImage(device(), scene, settings, 1);
    const gpu::FrameParams params = frameFor(scene, size, size);
    int quad = 0, litFloor = 0, shadowedFloor = 0;
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const Ray ray = pixelCenterRay(params, x, y);
        const glm::dvec3 p = ray.origin + (1.0 - ray.origin.y) / ray.direction.y * ray.direction;  // at y = 1
        if (std::abs(p.x) > 1.0 || std::abs(p.z) > 1.0) continue;
        // The checker cell under the pixel (u along +x, v along +z), away from the cells' edges.
        const double u = (p.x + 1.0) * 2.0, v = (p.z + 1.0) * 2.0;
        if (std::abs(u - std::round(u)) < 0.1 || std::abs(v - std::round(v)) < 0.1) continue;
        const bool solid = (int(u) + int(v)) % 2 == 0;
        const glm::vec4 pixel = image.at(x, y);
        if (solid) {
          EXPECT_GT(pixel.g, 0.0f) << "the quad (white) at " << x << "," << y;
          ++quad;
        } else {
          EXPECT_EQ(pixel.g, 0.0f) << "the red floor through a hole at " << x << "," << y;
          // The light straight above: the floor seen through a hole is lit through the same hole, up to the
          // parallax between the camera and the light (small here, and away from cell edges).
          if (pixel.r > 0.0f) ++litFloor;
          else ++shadowedFloor;
        }
      }
    }
    EXPECT_GT(quad, 500);
    EXPECT_GT(litFloor, 500);
    EXPECT_LT(shadowedFloor, litFloor / 20) << "the floor under the holes is lit through them";
  }
}

// The ray probe (both backends: the query loop and the pipeline's any-hit program) passes through the same holes:
// rays straight down meet the quad on its solid cells and the floor under its holes.
TEST_F(TextureRenderTest, ProbeRaysPassThroughAnAlphaMasksHoles) {
  Scene scene = quadOverRedFloor(alphaChecker());
  scene.materialTextures[0].alphaMode = gpu::kAlphaMask;
  scene.materialTextures[0].alphaCutoff = 0.5f;
  std::vector<gpu::ProbeRay> rays;
  std::vector<bool> solid;
  for (int cy = 0; cy < 4; ++cy) {
    for (int cx = 0; cx < 4; ++cx) {
      // The centre of checker cell (cx, cy): u along +x, v along +z over the quad's [-1, 1]^2.
      const glm::vec3 origin(-1.0f + 0.5f * (float(cx) + 0.5f), 5.0f, -1.0f + 0.5f * (float(cy) + 0.5f));
      rays.push_back({origin, 0.0f, glm::vec3(0.0f, -1.0f, 0.0f), 100.0f});
      solid.push_back((cx + cy) % 2 == 0);
    }
  }
  const std::vector<gpu::ProbeHit> hits = traceProbeRays(device(), scene, rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(hits[i].instance, solid[i] ? 0u : 1u) << "cell " << i;
    EXPECT_NEAR(hits[i].t, solid[i] ? 4.0f : 5.0f, 1e-4f) << "cell " << i;
  }
}

// Stochastic transparency: a quad of alpha 0.25 over the red floor shows, averaged over samples, a quarter of
// the quad and three quarters of the floor (the path integrator; z-test at a false-alarm rate of 1e-6).
TEST_F(TextureRenderTest, ABlendedSurfaceIsSeenInProportionToItsAlpha) {
  Scene scene = quadOverRedFloor(solidTexture({255, 255, 255, 255}));
  scene.materialTextures[0].alphaMode = gpu::kAlphaBlend;
  scene.materialTextures[0].alpha = 0.25f;
  scene.camera.position = {0.0f, 8.0f, 0.001f};
  scene.camera.yfov = glm::radians(10.0f);  // only the quad's middle in view
  // A far light: the quad's radiance is the same everywhere, so a pixel's green counts its quad samples.
  scene.lights[0].record = pointLight(glm::vec3(0.0f, 1000.0f, 0.0f), glm::vec3(1.0e6f));
  RenderSettings settings = settingsFor(scene, gpu::kIntegratorPath);
  settings.width = settings.height = 16;
  // Jittered camera rays: the transparency decision hashes the ray, so rays through one point decide alike.
  settings.jitter = true;
  const std::uint32_t spp = 256;
  const Image image = renderImage(device(), scene, settings, spp);
  // Each sample sees the quad (green > 0) or the floor (green 0); the fraction of quad samples per pixel is
  // green / green-of-the-quad, so test the fraction pooled over pixels with its binomial standard error.
  double greenSum = 0.0;
  for (std::uint32_t y = 0; y < 16; ++y) {
    for (std::uint32_t x = 0; x < 16; ++x) greenSum += image.at(x, y).g;
  }
  const Image opaque = [&] {
    Scene s = scene;
    s.materialTextures[0].alpha = 1.0f;
    return renderImage(device(), s, settings, 4);
  }();
  double quadGreen = 0.0;
  for (std::uint32_t y = 0; y < 16; ++y) {
    for (std::uint32_t x = 0; x < 16; ++x) quadGreen += opaque.at(x, y).g;
  }
  const double fraction = greenSum / quadGreen;
  const double n = 16.0 * 16.0 * spp;
  const double sigma = std::sqrt(0.25 * 0.75 / n);
  EXPECT_NEAR(fraction, 0.25, 5.0 * sigma) << "5 sigma: a false alarm once in 1.7 million runs";
}

}  // namespace
}  // namespace raylab::test
