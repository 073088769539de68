// glTF's material extensions end to end, from the file's JSON to the rendered pixel (docs/gltf.md, "Material
// extensions"): rows of unit quads, one material each, under two point lights at pixel centres (the direct
// integrator: each pixel is the sum over the lights of f(wi, wo) I |cos theta_i| / r^2).
//   - At its neutral value each extension renders bit for bit as the material without it.
//   - At a non-neutral value each renders the documented openpbr layer: the record is built here by hand from the
//     mapping table of docs/gltf.md, not by the loader, and f comes from the double-precision reference.
// The loader's own mapping is tested parameter by parameter in gltf_material_test.cpp; this checks that what it
// reads reaches the image as the table says. Not here: KHR_materials_anisotropy's non-neutral value (the quad has
// no UVs, so no tangent of the file's to check it along; its mapping is tested there, its direction in
// texture_render_test.cpp) and KHR_materials_volume's
// (attenuation along a path inside, the path integrator's Beer-Lambert test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdf_params/material_params.h"
#include "gltf_test_support.h"
#include "reference/brdf_reference.h"
#include "support/analytic.h"
#include "support/gpu_test.h"

namespace raylab::test {
namespace {

using nlohmann::json;

class GltfExtensionRenderTest : public GpuTest {};

constexpr double kSpacing = 1.25;  // quads [0, 1]^2 at (column, row) * kSpacing, in the plane z = 0, facing +z
constexpr std::uint32_t kWidth = 320, kHeight = 128;
const glm::dvec3 kAbove(4.0, -1.0, 3.0), kBelow(5.0, 2.5, -2.5), kIntensity(30.0, 24.0, 18.0);

// Two rows of quads with these materials, lit from above and below, seen from above at an angle. Both tests render
// the one scene (its openpbr layers and glTF's own BRDF): one kernel to compile, on each backend.
Scene rowsOf(const std::vector<json>& front, const std::vector<json>& back) {
  GltfBuilder builder;
  std::size_t columns = 0;
  for (const auto& [row, materials] : {std::pair{0, &front}, std::pair{1, &back}}) {
    for (std::size_t i = 0; i < materials->size(); ++i) {
      builder.addNode({{"mesh", builder.addQuad(builder.addMaterial((*materials)[i]))},
                       {"translation", {double(i) * kSpacing, double(row) * kSpacing, 0.0}}});
    }
    columns = std::max(columns, materials->size());
  }
  Scene scene = builder.load();
  const double middle = 0.5 * ((double(columns) - 1.0) * kSpacing + 1.0);
  scene.lights.clear();
  scene.lights.push_back({"above", pointLight(glm::vec3(kAbove), glm::vec3(kIntensity))});
  scene.lights.push_back({"below", pointLight(glm::vec3(kBelow), glm::vec3(kIntensity))});
  scene.camera.position = {float(middle), -4.0f, 6.5f};
  scene.camera.target = {float(middle), 1.1f, 0.0f};
  scene.camera.yfov = glm::radians(36.0f);
  return scene;
}

Image renderRows(const Device& device, const Scene& scene) {
  RenderSettings settings = pixelCentres(kWidth, kHeight);
  KernelOptions options;
  options.integrator = IntegratorChoice::kSlides;
  settings.kernel = kernelFor(scene, options);
  return renderImage(device, scene, settings, 1);
}

// glTF's metallic-roughness core as the loader maps it onto openpbr (docs/gltf.md): the base colour, metalness,
// roughness and glTF's index of 1.5, every layer off.
gpu::MaterialRecord openPbrBase(glm::vec3 baseColor, float metallic, float roughness) {
  gpu::MaterialRecord r = defaultRecord(modelId("openpbr"));
  setParam(r, "base_weight", glm::vec3(1.0f), "test");
  setParam(r, "base_color", baseColor, "test");
  setParam(r, "base_metalness", glm::vec3(metallic), "test");
  setParam(r, "base_diffuse_roughness", glm::vec3(0.0f), "test");
  setParam(r, "specular_weight", glm::vec3(1.0f), "test");
  setParam(r, "specular_color", glm::vec3(1.0f), "test");
  setParam(r, "specular_roughness", glm::vec3(roughness), "test");
  setParam(r, "specular_roughness_anisotropy", glm::vec3(0.0f), "test");
  setParam(r, "specular_ior", glm::vec3(1.5f), "test");
  setParam(r, "transmission_weight", glm::vec3(0.0f), "test");
  setParam(r, "coat_weight", glm::vec3(0.0f), "test");
  setParam(r, "fuzz_weight", glm::vec3(0.0f), "test");
  setParam(r, "thin_film_weight", glm::vec3(0.0f), "test");
  return r;
}

json core(glm::vec3 color, double metallic, double roughness) {
  return {{"baseColorFactor", {color.r, color.g, color.b, 1.0}}, {"metallicFactor", metallic},
          {"roughnessFactor", roughness}};
}

struct Case {
  std::string name;
  json material;                 // the glTF material, extension included
  gpu::MaterialRecord expected;  // the record the mapping table gives, built by hand
};

// A case: glTF's core factors and `extensions` in the file; in the record, openpbr's base of those factors with
// `layer`'s parameters set as the mapping table says.
Case layered(const std::string& name, glm::vec3 color, float metallic, float roughness, const json& extensions,
             const std::vector<std::pair<const char*, glm::vec3>>& layer) {
  gpu::MaterialRecord record = openPbrBase(color, metallic, roughness);
  for (const auto& [param, value] : layer) setParam(record, param, value, "test");
  return {name, {{"pbrMetallicRoughness", core(color, metallic, roughness)}, {"extensions", extensions}}, record};
}

std::vector<Case> nonNeutralCases() {
  const glm::vec3 white(1.0f);
  return {
      layered("KHR_materials_clearcoat", {0.5f, 0.05f, 0.02f}, 0.0f, 0.45f,
              {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.8}, {"clearcoatRoughnessFactor", 0.25}}}},
              {{"coat_weight", glm::vec3(0.8f)}, {"coat_roughness", glm::vec3(0.25f)}, {"coat_ior", glm::vec3(1.5f)},
               {"coat_color", white}, {"coat_darkening", glm::vec3(0.0f)}}),
      layered("KHR_materials_coat", {0.9f, 0.6f, 0.3f}, 1.0f, 0.3f,
              {{"KHR_materials_coat", {{"coatFactor", 1.0}, {"coatRoughnessFactor", 0.2}, {"coatIor", 1.6},
                                       {"coatColorFactor", {0.9, 0.7, 0.5}}, {"coatDarkeningFactor", 1.0}}}},
              {{"coat_weight", white}, {"coat_roughness", glm::vec3(0.2f)}, {"coat_ior", glm::vec3(1.6f)},
               {"coat_color", {0.9f, 0.7f, 0.5f}}, {"coat_darkening", white}}),
      // The sheen's colour is fuzz_weight = its largest channel times fuzz_color.
      layered("KHR_materials_sheen", {0.1f, 0.1f, 0.4f}, 0.0f, 0.6f,
              {{"KHR_materials_sheen", {{"sheenColorFactor", {0.8, 0.4, 0.2}}, {"sheenRoughnessFactor", 0.4}}}},
              {{"fuzz_weight", glm::vec3(0.8f)}, {"fuzz_color", {1.0f, 0.5f, 0.25f}},
               {"fuzz_roughness", glm::vec3(0.4f)}}),
      layered("KHR_materials_fuzz", {0.3f, 0.5f, 0.2f}, 0.0f, 0.5f,
              {{"KHR_materials_fuzz", {{"fuzzFactor", 0.7}, {"fuzzColorFactor", {0.9, 0.9, 1.0}},
                                       {"fuzzRoughnessFactor", 0.6}}}},
              {{"fuzz_weight", glm::vec3(0.7f)}, {"fuzz_color", {0.9f, 0.9f, 1.0f}},
               {"fuzz_roughness", glm::vec3(0.6f)}}),
      // The film's thickness in micrometres.
      layered("KHR_materials_iridescence", {0.95f, 0.95f, 0.95f}, 1.0f, 0.25f,
              {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.9}, {"iridescenceIor", 1.8},
                                              {"iridescenceThicknessMaximum", 450.0}}}},
              {{"thin_film_weight", glm::vec3(0.9f)}, {"thin_film_ior", glm::vec3(1.8f)},
               {"thin_film_thickness", glm::vec3(0.45f)}}),
      layered("KHR_materials_diffuse_roughness", {0.6f, 0.6f, 0.6f}, 0.0f, 0.5f,
              {{"KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", 0.8}}}},
              {{"base_diffuse_roughness", glm::vec3(0.8f)}}),
      // A half transmission, lit from below too: openpbr's transmission at depth 0, tinted by the base colour.
      layered("KHR_materials_transmission", {0.7f, 0.9f, 0.8f}, 0.0f, 0.35f,
              {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}},
              {{"transmission_weight", glm::vec3(0.5f)}, {"transmission_color", {0.7f, 0.9f, 0.8f}},
               {"transmission_depth", glm::vec3(0.0f)}}),
      // Diffuse transmission, lit from below too: a thin wall whose subsurface sheet passes all its light.
      layered("KHR_materials_diffuse_transmission", {0.3f, 0.6f, 0.3f}, 0.0f, 0.5f,
              {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.6},
                                                       {"diffuseTransmissionColorFactor", {0.9, 0.5, 0.2}}}}},
              {{"geometry_thin_walled", glm::vec3(1.0f)}, {"subsurface_weight", glm::vec3(0.6f)},
               {"subsurface_color", {0.9f, 0.5f, 0.2f}}, {"subsurface_scatter_anisotropy", glm::vec3(1.0f)}}),
      // Diffuse transmission into a volume: the same sheet, its light attenuated over the thickness,
      // attenuationColor^(0.5 / 1) = (0.7071, 0.8944, 1).
      layered("KHR_materials_diffuse_transmission with KHR_materials_volume", {0.3f, 0.6f, 0.3f}, 0.0f, 0.5f,
              {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.6},
                                                       {"diffuseTransmissionColorFactor", {0.9, 0.5, 0.2}}}},
               {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 1.0},
                                         {"attenuationColor", {0.5, 0.8, 1.0}}}}},
              {{"geometry_thin_walled", glm::vec3(1.0f)}, {"subsurface_weight", glm::vec3(0.6f)},
               {"subsurface_color", {0.9f * 0.7071068f, 0.5f * 0.8944272f, 0.2f}},
               {"subsurface_scatter_anisotropy", glm::vec3(1.0f)}}),
      // Dispersion on a half transmission with a clear volume, lit from below too: each channel refracted by its own
      // index (dispersion 0.8: V = 25).
      layered("KHR_materials_dispersion", {0.9f, 0.9f, 0.9f}, 0.0f, 0.3f,
              {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}},
               {"KHR_materials_volume", {{"thicknessFactor", 1.0}}},
               {"KHR_materials_dispersion", {{"dispersion", 0.8}}}},
              {{"transmission_weight", glm::vec3(0.5f)}, {"transmission_color", {0.9f, 0.9f, 0.9f}},
               {"transmission_depth", glm::vec3(0.0f)}, {"transmission_dispersion_scale", glm::vec3(0.8f)},
               {"transmission_dispersion_abbe_number", glm::vec3(20.0f)}}),
  };
}

// The back row's base: glTF's own BRDF, every quad alike.
const json kPlainBase = core({0.4f, 0.3f, 0.2f}, 0.3, 0.4);

// The back row without extensions.
std::vector<json> plainRow(std::size_t quads) { return std::vector<json>(quads, {{"pbrMetallicRoughness", kPlainBase}}); }

// The back row with each extension at its neutral value on that base, one quad each.
std::vector<json> neutralRow() {
  const auto with = [](const char* extension, const json& values) {
    return json{{"pbrMetallicRoughness", kPlainBase}, {"extensions", {{extension, values}}}};
  };
  return {with("KHR_materials_clearcoat", {{"clearcoatFactor", 0.0}, {"clearcoatRoughnessFactor", 0.7}}),
          with("KHR_materials_coat", {{"coatFactor", 0.0}, {"coatRoughnessFactor", 0.5}}),
          with("KHR_materials_sheen", {{"sheenColorFactor", {0.0, 0.0, 0.0}}, {"sheenRoughnessFactor", 0.5}}),
          with("KHR_materials_fuzz", {{"fuzzFactor", 0.0}}),
          with("KHR_materials_iridescence", {{"iridescenceFactor", 0.0}, {"iridescenceIor", 2.0}}),
          with("KHR_materials_anisotropy", {{"anisotropyStrength", 0.0}}),
          with("KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", 0.0}}),
          with("KHR_materials_transmission", {{"transmissionFactor", 0.0}}),
          with("KHR_materials_volume", {{"thicknessFactor", 0.0}}),
          with("KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.0}}),
          with("KHR_materials_dispersion", {{"dispersion", 0.0}})};
}

std::vector<json> materialsOf(const std::vector<Case>& cases) {
  std::vector<json> materials;
  for (const Case& c : cases) materials.push_back(c.material);
  return materials;
}

TEST_F(GltfExtensionRenderTest, EachExtensionAtItsNeutralValueRendersAsTheMaterialWithoutIt) {
  const std::vector<json> neutral = neutralRow();
  const std::vector<json> front = materialsOf(nonNeutralCases());
  const Image a = renderRows(device(), rowsOf(front, plainRow(neutral.size())));
  const Image b = renderRows(device(), rowsOf(front, neutral));
  std::size_t differing = 0, lit = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    differing += a.rgba[i] != b.rgba[i];
    lit += a.rgba[i] > 0.0f;
  }
  EXPECT_EQ(differing, 0u) << "a neutral extension changed the image";
  EXPECT_GT(lit, a.rgba.size() / 8) << "the rows are not in view";
}

TEST_F(GltfExtensionRenderTest, EachExtensionAtANonNeutralValueRendersItsDocumentedOpenPbrLayer) {
  const std::vector<Case> cases = nonNeutralCases();
  const Scene scene = rowsOf(materialsOf(cases), plainRow(neutralRow().size()));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(scene.materials[i].record.model, modelId("openpbr")) << cases[i].name;
  }
  const Image image = renderRows(device(), scene);
  if (const char* directory = std::getenv("RAYLAB_TEST_IMAGES"); directory != nullptr && *directory != '\0') {
    writePng(std::string(directory) + "/gltf_extensions.png", image, 0.0f, ToneMap::kClamp);
  }
  const gpu::FrameParams params = frameFor(scene, kWidth, kHeight);

  std::vector<int> compared(cases.size(), 0);
  std::vector<double> worst(cases.size(), 0.0);
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const Ray ray = pixelCenterRay(params, x, y);
      if (ray.direction.z >= -1e-3) continue;
      const glm::dvec3 p = ray.origin + (-ray.origin.z / ray.direction.z) * ray.direction;
      const double column = std::floor(p.x / kSpacing);
      const double u = p.x - column * kSpacing, v = p.y;
      // The front row, away from the quads' edges, where a pixel centre may fall either way in float32.
      if (column < 0 || column >= double(cases.size()) || u < 0.02 || u > 0.98 || v < 0.02 || v > 0.98) continue;
      const std::size_t i = std::size_t(column);
      const reference::Material material = reference::fromRecord(cases[i].expected);
      const glm::dvec3 wo = -ray.direction;  // the quad's frame is the world's: normal +z, tangent +x
      glm::dvec3 expected(0.0);
      for (const glm::dvec3& light : {kAbove, kBelow}) {
        const glm::dvec3 toLight = light - p;
        const glm::dvec3 wi = glm::normalize(toLight);
        expected += reference::eval(material, wi, wo) * kIntensity * std::abs(wi.z) / glm::dot(toLight, toLight);
      }
      const glm::vec4 pixel = image.at(x, y);
      for (int c = 0; c < 3; ++c) {
        // The device evaluates the layers in float32 from float32 positions: 3e-3 relative, and 1e-4 absolute
        // in the dark.
        const double error = std::abs(pixel[c] - expected[c]);
        worst[i] = std::max(worst[i], error / std::max(expected[c], 1e-4));
        EXPECT_NEAR(pixel[c], expected[c], 3e-3 * expected[c] + 1e-4)
            << cases[i].name << " at pixel " << x << "," << y << " channel " << c;
      }
      ++compared[i];
    }
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::printf("%-34s %5d pixels, worst relative difference %.2e\n", cases[i].name.c_str(), compared[i], worst[i]);
    EXPECT_GT(compared[i], 200) << cases[i].name << ": too few pixels on its quad";
  }
}

}  // namespace
}  // namespace raylab::test
