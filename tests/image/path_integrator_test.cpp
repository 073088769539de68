// The path integrator on scenes with known answers: a white furnace (a sphere of every energy-conserving model
// under a uniform environment renders its directional albedo), a Lambert plane under a uniform sky, an
// emitter seen directly, and D = 0 agreeing with the slides' direct integrator where both compute direct light.
//
// Statistics. Furnace pixels are grouped into four bins of cos(theta_o); in each bin the mean of (image -
// albedo) over its pixels is compared with zero by a z-test whose standard error comes from the spread of those
// differences (pixels are independent: the RNG is keyed by pixel). |z| < 4 per bin: a false-alarm rate of
// 6.3e-5 per bin, about 1.5e-3 for the whole test; the seed is fixed, so a run is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "reference/albedo.h"
#include "render/kernel_features.h"
#include "render/light_records.h"
#include "render/renderer.h"
#include "brdf_params/material_params.h"
#include "scene/shapes.h"
#include "shared/features.h"
#include "image/path_test_support.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

class PathIntegratorTest : public GpuTest {};

// A unit sphere at the origin seen from +z, under a uniform environment of radiance `background`.
Scene furnace(const gpu::MaterialRecord& material, glm::vec3 background) {
  Scene scene;
  scene.materials.push_back({"sphere", material});
  scene.spheres.push_back({glm::vec3(0.0f), 1.0f, 0});
  scene.background = background;
  scene.camera.position = {0.0f, 0.0f, 4.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.yfov = glm::radians(35.0f);
  return scene;
}

struct FurnaceCase {
  const char* label;
  gpu::MaterialRecord material;
  std::uint32_t maxDepth = 0;  // direct light alone sees a reflection's albedo; light through a sphere needs more
};

// Every model that conserves energy, with reflectance 1 in the lobe that carries it; isotropic parameters, so
// that the albedo depends on theta_o alone.
std::vector<FurnaceCase> furnaceCases() {
  return {
      {"lambert", material("lambert", {{"rho_d", 1.0f}})},
      {"phong s=20", material("phong", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"s", 20.0f}})},
      {"cooktorrance m=0.3", material("cooktorrance", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"m", 0.3f}})},
      {"ward_gmd 0.3", material("ward_gmd", {{"rho_d", 0.0f}, {"rho_s", 1.0f}, {"alpha_x", 0.3f}, {"alpha_y", 0.3f}})},
      {"ashikhmin_shirley 100", material("ashikhmin_shirley", {{"Rd", 0.0f}, {"Rs", 1.0f}, {"nu", 100.0f}, {"nv", 100.0f}})},
      {"lambert+cooktorrance", material("cooktorrance", {{"rho_d", 0.5f}, {"rho_s", 0.5f}, {"m", 0.1f}})},
      // The second library's energy-preserving models: white EON's albedo is 1 at every angle, and so, within
      // its tables, is a white GGX conductor's with Kulla & Conty's compensation.
      {"eon r=1", material("eon", {{"rho_d", 1.0f}, {"r", 1.0f}})},
      {"ggx_conductor 0.5 multiscatter", material("ggx_conductor", {{"alpha_x", 0.5f}, {"alpha_y", 0.5f}, {"eta", 0.01f},
                                                                   {"k", 20.0f}, {"multiscatter", 1.0f}})},
      // OpenPBR's white-furnace list (the CPU test sweeps it at the BSDF level): a white metal under a thin film (a
      // film over a perfect mirror reflects everything), compiled with the film and without the coat, and a white
      // diffuse base under a white coat and a white fuzz, compiled without the film.
      {"openpbr metal + thin film", material("openpbr", {{"base_color", 1.0f}, {"base_metalness", 1.0f},
                                                          {"specular_roughness", 0.5f}, {"thin_film_weight", 1.0f},
                                                          {"thin_film_thickness", 0.4f}, {"thin_film_ior", 1.8f}})},
      {"openpbr diffuse + coat + fuzz", material("openpbr", {{"base_color", 1.0f}, {"coat_weight", 1.0f}, {"coat_roughness", 0.2f},
                                                              {"fuzz_weight", 1.0f}, {"fuzz_roughness", 0.5f}})},
      // A smooth white translucent base: what the sphere reflects and what passes through it both come from the
      // environment, so the image is its albedo (reflection plus transmission) too.
      {"openpbr smooth translucent", material("openpbr", {{"base_color", 1.0f}, {"specular_roughness", 0.0f},
                                                           {"transmission_weight", 1.0f}}), 16},
      // Invariance under opacity: a ray passes the half-covered sphere's near side, its far side (from inside) or
      // both with probability 1/2 each time, and every way out sees white; the shadow rays and the light list see
      // the same coverage (kernel/alpha.glsl).
      {"openpbr diffuse + coat, opacity 0.5", material("openpbr", {{"base_color", 1.0f}, {"coat_weight", 1.0f},
                                                                    {"coat_roughness", 0.2f}, {"geometry_opacity", 0.5f}}),
       16},
  };
}

TEST_F(PathIntegratorTest, WhiteFurnaceRendersEachModelsDirectionalAlbedo) {
  constexpr std::uint32_t kSize = 40, kSpp = 128;
  for (const FurnaceCase& c : furnaceCases()) {
    const Scene scene = furnace(c.material, glm::vec3(1.0f));
    // A model's own features are compiled exactly when a material uses them: openpbr's coat only with a coat, its
    // film only with a film, its fuzz only with a fuzz.
    for (const ModelFeature& feature : modelInfo(c.material.model).features) {
      EXPECT_EQ((featuresOf(scene).features & feature.bit) != 0, getParam(c.material, feature.param).x > 0.0f)
          << c.label << ": " << feature.name;
    }
    const Image image = renderImage(device(), scene, pathSettings(kSize, c.maxDepth, scene), kSpp);
    const gpu::FrameParams params = frameFor(scene, kSize, kSize);
    const reference::Material reference = reference::fromRecord(c.material);
    // The reference albedo on a table in cos(theta_o), to 1e-5 relative (1e-7 took the cubature 100 s of this
    // test's 128, on the conductor and the film), linear between entries: the albedo is smooth in cos, and the
    // interpolation error (below 1e-5 here) is far under the noise the z-test resolves.
    constexpr int kTable = 65;
    std::vector<double> table(kTable);
    for (int i = 0; i < kTable; ++i) {
      const double cosine = std::max(1e-3, double(i) / (kTable - 1));
      table[i] = reference::directionalAlbedo(reference, reference::directionFromAngles(std::acos(cosine), 0.0),
                                              {1e-5, 20000}).value.g;
    }
    const auto albedoAt = [&](double cosine) {
      const double at = std::clamp(cosine, 0.0, 1.0) * (kTable - 1);
      const int i = std::min(kTable - 2, int(at));
      return table[i] + (at - i) * (table[i + 1] - table[i]);
    };
    double sum[4] = {}, sumSquares[4] = {};
    int count[4] = {};
    double worstLambert = 0.0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
      for (std::uint32_t x = 0; x < kSize; ++x) {
        const Ray ray = pixelCenterRay(params, x, y);
        double line = 0.0;
        const auto t = hitSphere(ray, glm::dvec3(0.0), 1.0, &line);
        if (!t || line > 0.97) continue;  // silhouette pixels: float hit points too close to grazing
        const glm::dvec3 n = glm::normalize(ray.origin + *t * ray.direction);
        const double cosO = glm::dot(n, -ray.direction);
        // Isotropic lobes (below): the albedo depends on theta_o only, whatever tangent the sphere has.
        const double measured = image.at(x, y).g;
        const double d = measured - albedoAt(cosO);
        const int bin = std::min(3, int(cosO * 4.0));
        sum[bin] += d;
        sumSquares[bin] += d * d;
        count[bin] += 1;
        if (std::string(c.label) == "lambert") worstLambert = std::max(worstLambert, std::abs(measured - 1.0));
      }
    }
    for (int bin = 0; bin < 4; ++bin) {
      if (count[bin] < 8) continue;
      const double mean = sum[bin] / count[bin];
      const double variance = std::max(sumSquares[bin] / count[bin] - mean * mean, 1e-14);
      const double z = mean / std::sqrt(variance / count[bin]);
      EXPECT_LT(std::abs(z), 4.0) << c.label << ", cos(theta_o) in [" << bin * 0.25 << ", " << (bin + 1) * 0.25
                                  << "): mean error " << mean << " over " << count[bin] << " pixels";
    }
    // f cos / pdf is exactly rho_d for cosine-sampled Lambert: no noise at all.
    if (std::string(c.label) == "lambert") {
      EXPECT_LT(worstLambert, 1e-5);
    }
  }
}

// openpbr's translucent base with a volume: light through a sphere of index 1.001 (no Fresnel to speak of, no
// bending: 1e-3 rad at most) and roughness 0 under a uniform white environment arrives attenuated by Beer-Lambert
// along the chord, exp(-sigma 2 sqrt(1 - b^2)) for a ray passing the centre at distance b, with
// sigma = -ln(transmission_color) / transmission_depth. With transmission_depth 0 there is no volume (the
// specification's limit, not an error): the colour tints the light once, on its way in, whatever the chord.
TEST_F(PathIntegratorTest, BeerLambertAttenuatesLightThroughATranslucentSphere) {
  constexpr std::uint32_t kSize = 32, kSpp = 16;
  const glm::vec3 colour(0.5f, 0.7f, 0.9f);
  for (const float depth : {0.0f, 0.8f}) {
    const gpu::MaterialRecord glass = material("openpbr", {{"specular_ior", 1.001f}, {"specular_roughness", 0.0f},
                                                           {"transmission_weight", 1.0f}, {"transmission_depth", depth}});
    gpu::MaterialRecord tinted = glass;
    setParam(tinted, "transmission_color", colour, "test");
    const Scene scene = furnace(tinted, glm::vec3(1.0f));
    const Image image = renderImage(device(), scene, pathSettings(kSize, 8, scene), kSpp);
    const gpu::FrameParams params = frameFor(scene, kSize, kSize);
    double worst = 0.0;
    int inside = 0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
      for (std::uint32_t x = 0; x < kSize; ++x) {
        const Ray ray = pixelCenterRay(params, x, y);
        double line = 0.0;
        if (!hitSphere(ray, glm::dvec3(0.0), 1.0, &line) || line > 0.9) continue;
        ++inside;
        const double chord = 2.0 * std::sqrt(1.0 - line * line);
        for (int c = 0; c < 3; ++c) {
          const double expected = depth > 0.0f ? std::pow(double(colour[c]), chord / depth) : double(colour[c]);
          worst = std::max(worst, std::abs(double(image.at(x, y)[c]) - expected));
        }
      }
    }
    ASSERT_GT(inside, 100);
    std::printf("translucent sphere, transmission_depth %.1f: worst |pixel - exp(-sigma chord)| = %.1e\n", depth, worst);
    // Each sample is nearly deterministic (F ~ 2.5e-7, a GGX lobe 0.001 wide): the bound is the interface's
    // single-scattering loss at roughness 0 and the float hit points, not noise.
    EXPECT_LT(worst, 5e-3) << "transmission_depth " << depth;
  }
}

// geometry_opacity is coverage: a ray meets each surface it crosses with probability `opacity`, decided anew at each
// crossing. A black openpbr surface (no diffuse, no specular, no emission) of opacity 0.3 under a uniform white sky
// therefore shows the sky with probability 0.7 through a plane and 0.7^2 = 0.49 through a sphere, whose far side is
// a second crossing (one coin for both sides would show 0.7). Pooled over the surface's pixels, the mean must match
// to |z| < 4 (a false alarm once in 16,000 runs); renderImage checks the pipeline backend bit for bit. At pixel
// centres (the settings here): each sample's coins are its own (kernel/raygen.glsl), or pixels would be 0 or 1.
TEST_F(PathIntegratorTest, GeometryOpacityIsTheChanceARayMeetsEachSurfaceItCrosses) {
  constexpr std::uint32_t kSize = 32, kSpp = 64;
  constexpr float kOpacity = 0.3f;
  const gpu::MaterialRecord black = material("openpbr", {{"base_color", 0.0f}, {"specular_weight", 0.0f},
                                                         {"geometry_opacity", kOpacity}});
  Scene plane;
  plane.materials.push_back({"black plane", black});
  plane.meshes.push_back(makeGroundPlane(50.0f, 0.0f));
  plane.instances.push_back({0, glm::mat4(1.0f), 0});
  plane.background = glm::vec3(1.0f);
  plane.camera.position = {0.0f, 2.0f, 3.0f};
  plane.camera.target = {0.0f, 0.0f, 0.0f};
  const Scene sphere = furnace(black, glm::vec3(1.0f));
  for (const auto& [scene, expected] : {std::pair<const Scene*, double>{&plane, 1.0 - kOpacity}, std::pair<const Scene*, double>{&sphere, std::pow(1.0 - kOpacity, 2.0)}}) {
    EXPECT_NE(featuresOf(*scene).features & gpu::kFeatureAlpha, 0u) << "opacity below 1 compiles the alpha test";
    const Image image = renderImage(device(), *scene, pathSettings(kSize, 4, *scene), kSpp);
    const gpu::FrameParams params = frameFor(*scene, kSize, kSize);
    double sum = 0.0, sumSquares = 0.0;
    int count = 0;
    for (std::uint32_t y = 0; y < kSize; ++y) {
      for (std::uint32_t x = 0; x < kSize; ++x) {
        const Ray ray = pixelCenterRay(params, x, y);
        double line = 0.0;
        const bool covered = scene == &sphere ? hitSphere(ray, glm::dvec3(0.0), 1.0, &line) && line < 0.9
                                              : ray.direction.y < -0.05;  // well inside the plane's edge of view
        if (!covered) continue;
        const double d = double(image.at(x, y).g) - expected;
        sum += d;
        sumSquares += d * d;
        ++count;
      }
    }
    ASSERT_GT(count, 100);
    const double mean = sum / count;
    const double z = mean / std::sqrt(std::max(sumSquares / count - mean * mean, 1e-14) / count);
    std::printf("opacity %.1f, %s: mean %.4f, expected %.4f (z = %.2f over %d pixels)\n", kOpacity,
                scene == &sphere ? "sphere" : "plane", mean + expected, expected, z, count);
    EXPECT_LT(std::abs(z), 4.0) << (scene == &sphere ? "sphere" : "plane") << ": mean " << mean + expected;
  }
}

// Lambert rho under a uniform sky of radiance L: every bounce ray escapes, so each sample is rho L exactly.
TEST_F(PathIntegratorTest, LambertPlaneUnderAUniformSkyIsRhoTimesTheSky) {
  Scene scene;
  scene.materials.push_back({"ground", lambertMaterial(glm::vec3(0.5f, 0.25f, 0.75f))});
  scene.meshes.push_back(makeGroundPlane(50.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.background = glm::vec3(2.0f);
  scene.camera.position = {0.0f, 2.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  for (std::uint32_t depth : {0u, 8u}) {
    const Image image = renderImage(device(), scene, pathSettings(32, depth, scene), 4);
    int plane = 0;
    for (std::uint32_t y = 0; y < 32; ++y) {
      for (std::uint32_t x = 0; x < 32; ++x) {
        const glm::vec4 v = image.at(x, y);
        if (v.g == 2.0f) continue;  // the sky itself
        ++plane;
        EXPECT_NEAR(v.r, 1.0f, 1e-5f);
        EXPECT_NEAR(v.g, 0.5f, 1e-5f);
        EXPECT_NEAR(v.b, 1.5f, 1e-5f);
      }
    }
    EXPECT_GT(plane, 400) << "the camera does not see the plane";
  }
}

TEST_F(PathIntegratorTest, AnEmitterSeenDirectlyShowsItsRadianceFromTheFrontOnly) {
  gpu::MaterialRecord emitter = lambertMaterial(glm::vec3(0.0f));
  emitter.emission = glm::vec3(2.0f, 1.0f, 0.5f);
  Scene scene = furnace(emitter, glm::vec3(0.0f));
  const Image image = renderImage(device(), scene, pathSettings(24, 4, scene), 2);
  const gpu::FrameParams params = frameFor(scene, 24, 24);
  int seen = 0;
  for (std::uint32_t y = 0; y < 24; ++y) {
    for (std::uint32_t x = 0; x < 24; ++x) {
      const bool hits = hitSphere(pixelCenterRay(params, x, y), glm::dvec3(0.0), 1.0).has_value();
      const glm::vec4 v = image.at(x, y);
      if (!hits) {
        EXPECT_EQ(v.r, 0.0f);
        continue;
      }
      ++seen;
      EXPECT_EQ(glm::vec3(v), emitter.emission) << x << ", " << y;
    }
  }
  EXPECT_GT(seen, 50);

  // From inside the sphere the camera sees its back faces, which emit nothing.
  scene.camera.position = {0.0f, 0.0f, 0.5f};
  const Image inside = renderImage(device(), scene, pathSettings(8, 4, scene), 1);
  for (float value : inside.rgba) {
    if (value != 1.0f) {
      EXPECT_EQ(value, 0.0f);  // alpha is 1
    }
  }
}

// With punctual lights only, a black background, no mirror and no glass, both integrators compute direct
// lighting at D = 0: the same next event estimation, so the same image to float precision.
TEST_F(PathIntegratorTest, AtDepthZeroThePathIntegratorEqualsTheSlidesDirectLighting) {
  Scene scene;
  scene.materials.push_back({"ground", lambertMaterial(glm::vec3(0.6f))});
  scene.materials.push_back({"ball", material("cooktorrance", {{"rho_d", 0.3f}, {"rho_s", 0.6f}, {"m", 0.2f}})});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.spheres.push_back({glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 1});
  scene.lights.push_back({"key", pointLight(glm::vec3(2.0f, 5.0f, 3.0f), glm::vec3(40.0f))});
  scene.camera.position = {0.0f, 2.0f, 6.0f};
  scene.camera.target = {0.0f, 0.8f, 0.0f};
  RenderSettings slides = pixelCentres(48, 48);
  slides.maxDepth = 0;
  const Image direct = renderImage(device(), scene, slides, 1);
  const Image path = renderImage(device(), scene, pathSettings(48, 0, scene), 1);
  double worst = 0.0;
  for (std::size_t i = 0; i < direct.rgba.size(); ++i) {
    worst = std::max(worst, double(std::abs(direct.rgba[i] - path.rgba[i])) / std::max(1e-3, double(direct.rgba[i])));
  }
  EXPECT_LT(worst, 1e-6) << "path at D = 0 and slides differ";
}

// A glossy sphere on a Lambert floor under a small bright emissive sphere and a dim emissive quad.
Scene areaLitScene(float lightRadius, glm::vec3 lightRadiance) {
  Scene scene;
  scene.materials.push_back({"floor", lambertMaterial(glm::vec3(0.7f))});
  scene.materials.push_back({"ball", material("cooktorrance", {{"rho_d", 0.3f}, {"rho_s", 0.7f}, {"m", 0.15f}})});
  gpu::MaterialRecord lamp = lambertMaterial(glm::vec3(0.0f));
  lamp.emission = lightRadiance;
  scene.materials.push_back({"lamp", lamp});
  scene.meshes.push_back(makeGroundPlane(20.0f, 0.0f));
  scene.instances.push_back({0, glm::mat4(1.0f), 0});
  scene.spheres.push_back({glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 1});
  scene.spheres.push_back({glm::vec3(1.5f, 3.0f, 1.0f), lightRadius, 2});
  scene.camera.position = {0.0f, 2.5f, 6.0f};
  scene.camera.target = {0.0f, 0.8f, 0.0f};
  return scene;
}

// MIS, BSDF sampling alone and light sampling alone are three unbiased estimators of one image. Per region a
// t-test over 16 independent runs (15 degrees of freedom) of the difference beyond 1e-5 of the image's
// brightness: |t| < 4.5 has a false-alarm rate of 4e-4 per region, about 1.3% over the 2 x 16 regions.
TEST_F(PathIntegratorTest, MisBsdfAndLightSamplingConvergeToTheSameImage) {
  const Scene scene = areaLitScene(0.3f, glm::vec3(40.0f));
  const RenderSettings mis = samplingSettings(56, 3, scene, gpu::kSamplingMis);
  EXPECT_LT(worstRegionT(device(), scene, mis, samplingSettings(56, 3, scene, gpu::kSamplingBsdf), 16, 32), 4.5)
      << "MIS against BSDF sampling";
  EXPECT_LT(worstRegionT(device(), scene, mis, samplingSettings(56, 3, scene, gpu::kSamplingLight), 16, 32), 4.5)
      << "MIS against light sampling";
}

// A small sphere of radiance L and radius r radiates like a point light of intensity L pi r^2: the Lambert
// floor at D = 0 matches the slides' point-light render to the sphere's size correction, O((r/d)^2) = 3e-4.
TEST_F(PathIntegratorTest, ASmallSphericalLightConvergesToThePointLightOfTheSamePower) {
  const float r = 0.05f;
  const glm::vec3 radiance(2000.0f);
  Scene sphereLit = areaLitScene(r, radiance);
  sphereLit.materials[1].record = lambertMaterial(glm::vec3(0.5f));
  Scene pointLit = sphereLit;
  pointLit.spheres.pop_back();
  pointLit.lights.push_back({"point", pointLight(glm::vec3(1.5f, 3.0f, 1.0f), radiance * (3.14159265f * r * r))});
  RenderSettings slides = pixelCentres(32, 32);
  slides.maxDepth = 0;
  const Image reference = renderImage(device(), pointLit, slides, 1);
  const Image area = renderImage(device(), sphereLit, pathSettings(32, 0, sphereLit), 64);
  double sumReference = 0.0, sumArea = 0.0;
  for (std::size_t i = 1; i < reference.rgba.size(); i += 4) {
    sumReference += reference.rgba[i];
    sumArea += area.rgba[i];
  }
  EXPECT_NEAR(sumArea / sumReference, 1.0, 3e-3) << "mean over the image";
}

// Light is additive: a scene lit by one light of every kind at once (point, spot, directional, headlight,
// emitting triangles and sphere, environment image) renders the sum of the scene lit by each alone. The
// combined render draws its emitters through the light-selection distribution (one of four by power, with MIS
// against BSDF sampling) where each single-light render has one light at probability 1: a wrong selection
// probability, a density missing it, or a kind's sampler disagreeing with its MIS density biases the sum. Per
// region a t-test over 12 independent runs (11 degrees of freedom) of all - sum(alone): |t| < 5 has a
// false-alarm rate of 4e-4 per region, 0.6% over the 16 regions.
TEST_F(PathIntegratorTest, EveryKindOfLightAtOnceRendersTheSumOfEachAlone) {
  // Every scene has the same geometry (an emitting panel, two triangles facing down, and a small lamp sphere are
  // there, black, when they do not emit): only the light differs, so the images add up.
  Scene base = areaLitScene(0.2f, glm::vec3(0.0f));
  gpu::MaterialRecord panel = lambertMaterial(glm::vec3(0.0f));
  base.materials.push_back({"panel", panel});
  base.meshes.push_back(makeGroundPlane(1.0f, 0.0f));
  const glm::mat4 above = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 3.5f, -1.0f)), 3.14159265f,
                                      glm::vec3(1.0f, 0.0f, 0.0f));
  base.instances.push_back({1, above, 3});
  const glm::vec3 panelRadiance(6.0f, 5.0f, 4.0f), lampRadiance(30.0f);
  Environment sky;  // brighter towards +x and up
  sky.path = "test";
  sky.width = 16;
  sky.height = 8;
  for (std::uint32_t y = 0; y < sky.height; ++y) {
    for (std::uint32_t x = 0; x < sky.width; ++x) sky.texels.push_back(glm::vec3(0.1f + 0.05f * x * (8 - y) / 8.0f));
  }
  sky.brightest = 0.85f;
  PunctualLight spot = pointLight(glm::vec3(-2.0f, 4.0f, 1.0f), glm::vec3(30.0f));
  spot.type = gpu::kLightSpot;
  spot.direction = glm::normalize(glm::vec3(2.0f, -4.0f, -1.0f));
  spot.cosInner = std::cos(0.3f);
  spot.cosOuter = std::cos(0.5f);
  PunctualLight sun = pointLight(glm::vec3(0.0f), glm::vec3(0.8f));
  sun.type = gpu::kLightDirectional;
  sun.direction = glm::normalize(glm::vec3(-1.0f, -2.0f, -0.5f));
  PunctualLight headlight = pointLight(glm::vec3(0.3f, 0.2f, 0.0f), glm::vec3(3.0f));
  headlight.type = gpu::kLightHeadlight;
  const std::vector<Light> punctual = {{"point", pointLight(glm::vec3(2.0f, 4.0f, 3.0f), glm::vec3(20.0f))},
                                       {"spot", spot},
                                       {"sun", sun},
                                       {"headlight", headlight}};

  std::vector<Scene> alone;
  for (const Light& light : punctual) {
    alone.push_back(base);
    alone.back().lights = {light};
  }
  alone.push_back(base);
  alone.back().materials[3].record.emission = panelRadiance;
  alone.push_back(base);
  alone.back().materials[2].record.emission = lampRadiance;
  alone.push_back(base);
  alone.back().environment = sky;
  Scene all = base;
  all.lights = punctual;
  all.materials[3].record.emission = panelRadiance;
  all.materials[2].record.emission = lampRadiance;
  all.environment = sky;
  EXPECT_EQ(lightKindsOf(all), (1u << gpu::kLightKindCount) - 1) << "a kind of light is missing from the test";

  constexpr std::uint32_t kRuns = 12, kSpp = 32, kSize = 32;
  constexpr int kRegions = 4;
  // Region means of each run (seed 1..kRuns), one renderer per scene.
  const auto runMeans = [&](const Scene& scene) {
    GpuScene gpuScene = uploadScene(device(), scene);
    Renderer renderer = createRenderer(device(), gpuScene, scene, samplingSettings(kSize, 2, scene, gpu::kSamplingMis));
    std::vector<std::vector<double>> means;
    for (std::uint32_t run = 1; run <= kRuns; ++run) {
      renderer.params.seed = run;
      resetAccumulation(device(), renderer);
      renderSamples(device(), renderer, kSpp);
      means.push_back(regionMeans(readImage(device(), renderer), kRegions, kRegions));
    }
    EXPECT_EQ(renderer.droppedSamples, 0u);
    destroyRenderer(device(), renderer);
    destroyGpuScene(device(), gpuScene);
    return means;
  };
  std::vector<std::vector<double>> d = runMeans(all);  // then minus each scene alone: d[run][region]
  double level = 0.0;
  for (const std::vector<double>& run : d) {
    for (double v : run) level += v / double(run.size() * kRuns);
  }
  for (const Scene& scene : alone) {
    const std::vector<std::vector<double>> m = runMeans(scene);
    for (std::size_t run = 0; run < kRuns; ++run) {
      for (std::size_t i = 0; i < d[run].size(); ++i) d[run][i] -= m[run][i];
    }
  }
  std::vector<std::vector<double>> differences(kRegions * kRegions);
  for (const std::vector<double>& run : d) {
    for (std::size_t i = 0; i < run.size(); ++i) differences[i].push_back(run[i]);
  }
  ASSERT_GT(level, 0.01);
  for (std::size_t region = 0; region < differences.size(); ++region) {
    const std::vector<double>& d = differences[region];
    double mean = 0.0, squares = 0.0;
    for (double v : d) mean += v / double(d.size());
    for (double v : d) squares += (v - mean) * (v - mean);
    const double standardError = std::sqrt(squares / double(d.size() - 1) / double(d.size()));
    EXPECT_LT(std::abs(mean), 5.0 * standardError + 1e-5 * level) << "region " << region << ": all - sum(alone) = " << mean;
  }
}

}  // namespace
}  // namespace raylab::test
