// Emissive textures (glTF 3.9.3): the radiance seen at each point of an emitter is its factor times the texel the
// CPU reference (scene/texture_lookup.h) reads there, through the use's UV set, transform, wrap modes, filter and
// sRGB decoding; next event estimation sees the same texels, so light sampling, BSDF sampling and their MIS
// combination converge to one image; and the light-selection distribution weighs each triangle by the texture's
// mean over it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "brdf_params/material_params.h"
#include "path_test_support.h"
#include "render/kernel_features.h"
#include "render/light_records.h"
#include "scene/texture_lookup.h"
#include "shared/features.h"
#include "support/analytic.h"
#include "support/gpu_test.h"
#include "texture_scenes.h"

namespace raylab::test {
namespace {

class EmissiveTextureTest : public GpuTest {};

// A black Lambert material emitting `factor` times texture 0 through `ref`.
Scene emitterScene(const Mesh& mesh, const Texture& emissive, const gpu::TextureRef& ref, glm::vec3 factor) {
  Scene scene;
  scene.name = "emissive texture";
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.textures.push_back(emissive);
  gpu::MaterialTextures uses = noMaterialTextures();
  uses.refs[gpu::kTextureEmissive] = ref;
  scene.materialTextures.push_back(uses);
  gpu::MaterialRecord record = lambertMaterial(glm::vec3(0.0f));
  record.emission = factor;
  record.textures = 0;
  scene.materials.push_back({"emitter", record});
  return scene;
}

// KHR_texture_transform's matrix: translation times rotation times scale (glTF's extension text).
gpu::TextureRef transformedRef(std::uint32_t texCoord, glm::vec2 offset, float rotation, glm::vec2 scale) {
  gpu::TextureRef ref = textureRef(0);
  ref.texCoord = texCoord;
  const float c = std::cos(rotation), s = std::sin(rotation);
  ref.row0 = glm::vec3(c * scale.x, s * scale.y, offset.x);
  ref.row1 = glm::vec3(-s * scale.x, c * scale.y, offset.y);
  return ref;
}

// Six distinct texels, so that every wrap and filter choice shows in the value read.
const std::vector<std::uint8_t> kSixTexels = {10, 200, 30, 255, 250, 40, 90, 255, 128, 128, 128, 255,
                                              0, 60, 220, 255, 180, 255, 5, 255, 70, 20, 160, 255};

// Seen straight from above by pixel-centre rays, with the path integrator at depth 0, each pixel is L_e at its
// point: the factor times the CPU reference's lookup. Repeat, mirror and clamp, bilinear and nearest, both UV
// sets, 8- and 16-bit texels, a transform that rotates, scales and offsets the UVs over several periods.
TEST_F(EmissiveTextureTest, EachPointEmitsTheTexelTheCpuReferenceReads) {
  struct Case {
    std::uint32_t wrapS, wrapT;
    bool nearest;
    std::uint32_t texCoord;
    bool sixteen = false;  // RGBA16 texels, between the 8-bit values
  };
  const glm::vec3 factor(2.0f, 1.0f, 0.5f);
  Mesh mesh = texturedQuad(1.0f);
  mesh.uvs1 = {{0.3f, 1.0f}, {0.9f, 0.8f}, {1.1f, -0.2f}, {0.2f, 0.1f}};  // a second, skewed parameterisation
  for (const Case& c : {Case{gpu::kWrapRepeat, gpu::kWrapMirror, false, 0}, Case{gpu::kWrapMirror, gpu::kWrapClamp, true, 1},
                        Case{gpu::kWrapClamp, gpu::kWrapRepeat, false, 1},
                        Case{gpu::kWrapRepeat, gpu::kWrapRepeat, false, 0, true}}) {
    Texture t = solidTexture(kSixTexels, 3, 2);
    if (c.sixteen) {
      for (std::uint8_t v : kSixTexels) t.rgba16.push_back(std::uint16_t(std::min(65535, v * 257 + 97)));
      t.rgba.clear();
    }
    t.wrapS = c.wrapS;
    t.wrapT = c.wrapT;
    t.nearest = c.nearest;
    const gpu::TextureRef ref = transformedRef(c.texCoord, {-0.3f, 0.4f}, 0.5f, {2.7f, 1.9f});
    Scene scene = emitterScene(mesh, t, ref, factor);
    scene.camera.position = {0.0f, 4.0f, 0.01f};
    scene.camera.yfov = glm::radians(26.0f);  // the quad fills the image
    const std::uint32_t size = 40;
    const RenderSettings settings = pathSettings(size, 0, scene);
    const Image image = renderImage(device(), scene, settings, 1);
    const gpu::FrameParams params = frameFor(scene, size, size);
    int compared = 0;
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const Ray ray = pixelCenterRay(params, x, y);
        const glm::dvec3 p = ray.origin - ray.origin.y / ray.direction.y * ray.direction;
        if (std::abs(p.x) > 0.999 || std::abs(p.z) > 0.999) continue;
        // The point's barycentrics in the mesh's triangles give both UV sets, as the kernel interpolates them.
        const glm::dvec2 uv0((p.x + 1.0) / 2.0, (p.z + 1.0) / 2.0);
        const bool lower = uv0.x >= uv0.y;  // triangle (0, 2, 1) holds u >= v
        const glm::dvec2 a(mesh.uvs1[0]), corner(mesh.uvs1[2]), b(lower ? mesh.uvs1[1] : mesh.uvs1[3]);
        const glm::dvec2 uv1 = lower ? a + uv0.x * (b - a) + uv0.y * (corner - b)
                                     : a + uv0.y * (b - a) + uv0.x * (corner - b);
        const glm::dvec2 uv = textureUv(ref, uv0, uv1);
        if (c.nearest) {
          // The nearest texel changes across a texel edge: skip points within float error of one.
          const glm::dvec2 texel = uv * glm::dvec2(t.width, t.height);
          if (std::abs(texel.x - std::round(texel.x)) < 1e-3 || std::abs(texel.y - std::round(texel.y)) < 1e-3) continue;
        }
        const glm::dvec3 expected = glm::dvec3(factor) * glm::dvec3(sampleTexture(t, uv, true));
        const glm::vec4 pixel = image.at(x, y);
        for (int k = 0; k < 3; ++k) {
          ASSERT_NEAR(pixel[k], expected[k], 2e-4 * std::max(1.0, expected[k]))
              << "channel " << k << " at pixel " << x << "," << y << ", wrap " << c.wrapS << "/" << c.wrapT
              << (c.nearest ? " nearest" : " bilinear") << ", TEXCOORD_" << c.texCoord << (c.sixteen ? ", 16-bit" : "");
        }
        ++compared;
      }
    }
    EXPECT_GT(compared, 1200);
  }
}

// A 2x2 texture (nearest) of one bright green texel, one black and two dimmer ones, on a downward-facing emitter
// over a grey floor. Only the texture says where on the emitter light leaves: an estimator that ignored it (the
// factor alone) would be three times too bright, one that misplaced the texels would be lopsided.
Scene texturedLampOverFloor() {
  Texture t = solidTexture({0, 255, 0, 255, 0, 0, 0, 255, 90, 90, 0, 255, 20, 40, 20, 255}, 2, 2);
  t.nearest = true;
  Mesh lamp = texturedQuad(0.5f);
  for (glm::vec3& n : lamp.normals) n = -n;
  lamp.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from below: it emits downwards
  Scene scene = emitterScene(lamp, t, textureRef(0), glm::vec3(30.0f));
  scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  scene.meshes.push_back(texturedQuad(2.0f));
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.5f))});
  scene.instances.push_back({1, glm::mat4(1.0f), 1});
  // The floor around the lamp's foot, seen from above at an angle; no grazing floor far away, where BSDF
  // sampling meets the lamp too rarely for 16 samples a pixel to estimate.
  scene.camera.position = {0.0f, 3.5f, 2.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(45.0f);
  return scene;
}

// Light sampling (the texture at the sampled point) against BSDF sampling (the texture where a continuation
// meets the emitter), and MIS against BSDF sampling: 16 pairs of independent renders each, |t| < 4.5 over 16
// regions (t with 15 degrees of freedom: a false alarm about once in 2,000 runs of this test).
TEST_F(EmissiveTextureTest, NextEventEstimationSeesTheTextureAsContinuationsDo) {
  const Scene scene = texturedLampOverFloor();
  const RenderSettings bsdf = samplingSettings(32, 0, scene, gpu::kSamplingBsdf);
  EXPECT_LT(worstRegionT(device(), scene, samplingSettings(32, 0, scene, gpu::kSamplingLight), bsdf, 16, 16), 4.5)
      << "light sampling against BSDF sampling";
  EXPECT_LT(worstRegionT(device(), scene, samplingSettings(32, 0, scene, gpu::kSamplingMis), bsdf, 16, 16), 4.5)
      << "MIS against BSDF sampling";
}

// The selection distribution: a quad whose two triangles lie on the two texels of a white-and-black texture
// (nearest) gives all its power to the white one; the black one is never picked.
TEST(EmissiveTextureLights, EachTriangleIsChosenByTheTexturesMeanOverIt) {
  Mesh mesh = texturedQuad(1.0f);
  // The diagonal from vertex 0 to 2 runs along u = 0.5, the texel edge: triangle (0, 2, 1) covers u > 0.5.
  mesh.uvs = {{0.5f, 0.0f}, {1.0f, 0.5f}, {0.5f, 1.0f}, {0.0f, 0.5f}};
  Texture t = solidTexture({0, 0, 0, 255, 255, 255, 255, 255}, 2, 1);
  t.nearest = true;
  const Scene scene = emitterScene(mesh, t, textureRef(0), glm::vec3(3.0f));
  EmitterSurfaces surfaces;
  surfaces.instanceRecords = {7};
  surfaces.textures = scene.textures;
  const SceneLights lights = sceneLights(scene, EnvironmentTables{}, surfaces);
  ASSERT_EQ(lights.records.size(), 2u);
  EXPECT_EQ(lights.records[0].pmf, 1.0f) << "triangle (0, 2, 1), on the white texel";
  EXPECT_EQ(lights.records[1].pmf, 0.0f) << "triangle (0, 3, 2), on the black texel";
  EXPECT_NEAR(lights.powers[0], kPi * 3.0 * 2.0, 1e-5) << "pi L_e A with the texel's mean, 1";
  for (const gpu::LightRecord& record : lights.records) {
    EXPECT_EQ(record.texturedInstance, 7u) << "the kernels find the surface through its instance record";
    EXPECT_EQ(record.radiance, glm::vec3(3.0f)) << "the factor; the texture multiplies it in the kernel";
  }
  EXPECT_EQ(lights.records[1].primitive, 1u);
}

// Broken UVs (NaN, infinite, far off) under an emissive texture still give every triangle a finite power.
TEST(EmissiveTextureLights, BrokenUvsGiveFinitePowers) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Mesh mesh = texturedQuad(1.0f);
  mesh.uvs = {{nan, 0.0f}, {inf, -inf}, {1e30f, -1e30f}, {0.5f, nan}};
  const Scene scene = emitterScene(mesh, solidTexture(kSixTexels, 3, 2), textureRef(0), glm::vec3(3.0f));
  EmitterSurfaces surfaces;
  surfaces.instanceRecords = {0};
  surfaces.textures = scene.textures;
  const SceneLights lights = sceneLights(scene, EnvironmentTables{}, surfaces);
  for (double power : lights.powers) EXPECT_TRUE(std::isfinite(power) && power >= 0.0) << power;
}

// Live edits of emission (the viewer's panel, a sweep): the records updateEmitters leaves are the ones a fresh
// upload of the edited scene makes, radiance, power and selection alike; a material that starts emitting where
// there are no records is reported, and the one edited back to black is never picked.
TEST(EmissiveTextureLights, AnEmissionEditUpdatesTheRecordsAsAFreshUploadMakesThem) {
  Mesh mesh = texturedQuad(1.0f);
  Texture t = solidTexture(kSixTexels, 3, 2);
  Scene scene = emitterScene(mesh, t, textureRef(0), glm::vec3(3.0f));
  scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 2.0f)), 0});
  scene.materials.push_back({"dark", lambertMaterial(glm::vec3(0.5f))});
  scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 4.0f)), 1});
  EmitterSurfaces surfaces;
  surfaces.instanceRecords = {0, 1, 2};
  surfaces.textures = scene.textures;
  SceneLights lights = sceneLights(scene, EnvironmentTables{}, surfaces);
  ASSERT_EQ(lights.records.size(), 4u) << "two emitting quads";

  scene.materials[0].record.emission = glm::vec3(0.5f, 7.0f, 2.0f);
  EXPECT_TRUE(updateEmitters(lights, scene.materials));
  const SceneLights fresh = sceneLights(scene, EnvironmentTables{}, surfaces);
  ASSERT_EQ(fresh.records.size(), lights.records.size());
  for (std::size_t i = 0; i < fresh.records.size(); ++i) {
    EXPECT_EQ(lights.records[i].radiance, fresh.records[i].radiance) << "record " << i;
    EXPECT_EQ(lights.records[i].pmf, fresh.records[i].pmf) << "record " << i;
    EXPECT_EQ(lights.records[i].cdf, fresh.records[i].cdf) << "record " << i;
    EXPECT_EQ(lights.powers[i], fresh.powers[i]) << "record " << i;
  }
  scene.materials[0].record.emission = glm::vec3(0.0f);
  EXPECT_TRUE(updateEmitters(lights, scene.materials));
  for (const gpu::LightRecord& record : lights.records) EXPECT_EQ(record.pmf, 0.0f) << "a black light is never picked";
  scene.materials[1].record.emission = glm::vec3(1.0f);
  EXPECT_FALSE(updateEmitters(lights, scene.materials)) << "the dark quad has no records to sample";
}

}  // namespace
}  // namespace raylab::test
