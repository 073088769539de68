// glTF materials: extras.raylab models and parameters, the metallic-roughness mapping (docs/scenes.md),
// KHR_materials_ior and KHR_materials_transmission, and base-colour textures.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include "gltf_test_support.h"
#include "gltf_read/gltf_materials.h"
#include "brdf_params/material_params.h"

namespace raylab::test {
namespace {

using nlohmann::json;

// 2x2 RGB: red, green / blue, white.
constexpr const char* kPngRgb =
    "data:image/png;base64,"
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEklEQVR42mP4z8DAAMIM/4EAAB/uBfvxq7p3AAAAAElFTkSuQmCC";
// 3x1 grey, 16 bits: 0x0000, 0x8080, 0xffff.
constexpr const char* kPngGrey16 =
    "data:image/png;base64,"
    "iVBORw0KGgoAAAANSUhEUgAAAAMAAAABEAAAAABuG5crAAAAD0lEQVR42mNgYGho+P8fAAaEAv//G2LxAAAAAElFTkSuQmCC";
// 2x1 grey and alpha: (10, 20), (200, 250).
constexpr const char* kPngGreyAlpha =
    "data:image/png;base64,"
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAQAAABeK7cBAAAADUlEQVR42mPgEjnxCwAC8wHhibjEdAAAAABJRU5ErkJggg==";

void expectNear(glm::vec3 actual, glm::vec3 expected, const std::string& what, float tolerance = 1e-5f) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " component " << i;
}


// A scene with one quad using the given material.
Scene loadMaterial(const json& material) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad(b.addMaterial(material))}});
  return b.load();
}

std::string materialError(const json& material) {
  return errorOf([&] { loadMaterial(material); });
}

TEST(GltfMaterial, ExtrasRaylabChoosesTheModelAndItsParameters) {
  const Scene scene = loadMaterial({{"name", "brushed"},
                                    {"extras", {{"raylab", {{"model", "ward"}, {"rho_d", {0.1, 0.1, 0.1}},
                                                            {"rho_s", {0.9, 0.9, 0.9}}, {"alpha_x", 0.1},
                                                            {"alpha_y", 0.4}, {"delta", 0.25}}}}}});
  ASSERT_EQ(scene.materials.size(), 1u);
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(scene.materials[0].name, "brushed");
  EXPECT_EQ(r.model, modelId("ward"));
  expectNear(getParam(r, "rho_d"), glm::vec3(0.1f), "rho_d");
  expectNear(getParam(r, "rho_s"), glm::vec3(0.9f), "rho_s");
  EXPECT_FLOAT_EQ(getParam(r, "alpha_x").x, 0.1f);
  EXPECT_FLOAT_EQ(getParam(r, "alpha_y").x, 0.4f);
  EXPECT_FLOAT_EQ(r.delta, 0.25f);
}

TEST(GltfMaterial, EveryModelOfTheTableCanBeChosen) {
  for (const ModelInfo& model : allModels()) {
    const json raylab = {{"extras", {{"raylab", {{"model", std::string(model.name)}}}}}};
    if (findFileParam(model) != nullptr) {
      // A model reading a file needs it named (measured_cli_test renders one from a scene's folder).
      EXPECT_NE(materialError(raylab).find(std::string(model.name) + " needs its file"), std::string::npos) << model.name;
      continue;
    }
    const Scene scene = loadMaterial(raylab);
    EXPECT_EQ(scene.materials[0].record.model, model.id) << model.name;
  }
}

TEST(GltfMaterial, ExtrasRaylabErrorsNameTheMaterial) {
  const auto error = [](const json& raylab) {
    return materialError({{"name", "gold"}, {"extras", {{"raylab", raylab}}}});
  };
  const std::string unknownKey = error({{"model", "phong"}, {"alpha_x", 0.2}});
  EXPECT_NE(unknownKey.find("test: material 0 'gold': extras.raylab: 'alpha_x' is not a parameter of phong"),
            std::string::npos) << unknownKey;
  const std::string outOfRange = error({{"model", "cooktorrance"}, {"m", 2.0}});
  EXPECT_NE(outOfRange.find("test: material 0 'gold': extras.raylab: m = 2 is outside [0.001, 1]"), std::string::npos)
      << outOfRange;
  const std::string unknownModel = error({{"model", "lambrt"}});
  EXPECT_NE(unknownModel.find("material 0 'gold': extras.raylab.model: \"lambrt\" is not a model"),
            std::string::npos) << unknownModel;
  const std::string notRgb = error({{"model", "lambert"}, {"rho_d", 0.5}});
  EXPECT_NE(notRgb.find("material 0 'gold': extras.raylab.rho_d: expected [r, g, b], found 0.5"), std::string::npos)
      << notRgb;
  const std::string notNumber = error({{"model", "phong"}, {"s", "shiny"}});
  EXPECT_NE(notNumber.find("extras.raylab.s: expected a number"), std::string::npos) << notNumber;
  const std::string delta = error({{"delta", 1.5}});
  EXPECT_NE(delta.find("delta = 1.5 is outside [0, 1]"), std::string::npos) << delta;
}

// extras.raylab names a metal as the CLI does; the object's other values refine it (JSON objects are unordered).
TEST(GltfMaterial, ExtrasRaylabNamesAMetal) {
  gpu::MaterialRecord record = defaultRecord(modelId("lambert"));
  gltf::applyRaylabMaterial(record, {{"model", "ggx_conductor"}, {"metal", "Cu"}, {"alpha_x", 0.05}},
                            "file: material 1 'pipe'");
  EXPECT_FLOAT_EQ(getParam(record, "eta").y, 0.92375f);
  EXPECT_FLOAT_EQ(getParam(record, "alpha_x").x, 0.05f);
  const std::string error = errorOf([&] {
    gltf::applyRaylabMaterial(record, {{"model", "ggx_conductor"}, {"metal", 79}}, "file: material 1 'pipe'");
  });
  EXPECT_NE(error.find("file: material 1 'pipe': extras.raylab.metal: expected a name, found 79"), std::string::npos)
      << error;
}

TEST(GltfMaterial, NonFiniteValuesAreRejected) {
  // JSON text cannot hold NaN: such a file fails to parse, naming the line and column.
  const std::string text = R"({"asset": {"version": "2.0"},
      "materials": [{"extras": {"raylab": {"model": "lambert", "rho_d": [NaN, 0, 0]}}}]})";
  const std::string parse = errorOf([&] { loadGltfText(text, "", "nan.gltf", {}); });
  EXPECT_NE(parse.find("nan.gltf: not valid JSON: parse error at line 2"), std::string::npos) << parse;
  // A NaN that reaches the material (from code) is refused with the same message as an out-of-range value.
  gpu::MaterialRecord record = defaultRecord(modelId("lambert"));
  const json raylab = {{"rho_d", {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}}};
  const std::string nan = errorOf([&] { gltf::applyRaylabMaterial(record, raylab, "file: material 3 'x'"); });
  EXPECT_NE(nan.find("file: material 3 'x': extras.raylab: rho_d = nan is outside [0, 1]"), std::string::npos) << nan;
  const json huge = {{"model", "phong"}, {"s", 1e300}};
  const std::string inf = errorOf([&] { gltf::applyRaylabMaterial(record, huge, "file: material 3 'x'"); });
  EXPECT_NE(inf.find("s = inf is outside [1, 10000]"), std::string::npos) << inf;
}

// A material without extras.raylab is glTF's own BRDF (Appendix B), its factors unchanged, glTF's defaults
// (metallic 1, roughness 1, ior 1.5) where the file says nothing.
TEST(GltfMaterial, MetallicRoughnessIsGltfPbrWithTheFactorsAsTheyAre) {
  const Scene scene = loadMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.1, 1.0}},
                                                              {"metallicFactor", 0.25}, {"roughnessFactor", 0.5}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("gltf_pbr"));
  expectNear(getParam(r, "base_color"), {0.8f, 0.2f, 0.1f}, "base_color");
  EXPECT_FLOAT_EQ(getParam(r, "metallic").x, 0.25f);
  EXPECT_FLOAT_EQ(getParam(r, "roughness").x, 0.5f);
  EXPECT_NEAR(getParam(r, "ior").x, 1.5f, 1e-6f) << "glTF's default ior";
  EXPECT_FLOAT_EQ(r.delta, 0.0f);

  const Scene defaults = loadMaterial({{"pbrMetallicRoughness", json::object()}});
  const gpu::MaterialRecord& d = defaults.materials[0].record;
  expectNear(getParam(d, "base_color"), glm::vec3(1.0f), "glTF's default base colour");
  EXPECT_FLOAT_EQ(getParam(d, "metallic").x, 1.0f) << "glTF's default metallic";
  EXPECT_FLOAT_EQ(getParam(d, "roughness").x, 1.0f) << "glTF's default roughness";
}

// gltf_pbr's f0 formula holds for any ior, but its table stops at 3: a valid file beyond it still loads, with the
// ior used as 3 and a warning that says so.
TEST(GltfMaterial, AnIorAboveGltfPbrsRangeIsUsedAsItsMaximumWithAWarning) {
  WarningCapture warnings;
  const Scene scene = loadMaterial({{"name", "rutile"}, {"extensions", {{"KHR_materials_ior", {{"ior", 4.0}}}}},
                                    {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
  EXPECT_FLOAT_EQ(getParam(scene.materials[0].record, "ior").x, 3.0f);
  EXPECT_EQ(warnings.count("KHR_materials_ior.ior = 4 is above gltf_pbr's 3; using 3"), 1);
}

TEST(GltfMaterial, IorSetsEtaAndFullTransmissionMakesGlass) {
  const Scene water = loadMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}}}},
                                    {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
  EXPECT_EQ(water.materials[0].record.model, modelId("gltf_pbr"));
  EXPECT_NEAR(getParam(water.materials[0].record, "ior").x, 1.33f, 1e-5f);

  const Scene glass = loadMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 1.7}}},
                                                    {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}},
                                    {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 1.0, 0.95, 1.0}},
                                                              {"roughnessFactor", 0.0}}}});
  const gpu::MaterialRecord& g = glass.materials[0].record;
  EXPECT_EQ(g.model, modelId("glass"));
  EXPECT_NEAR(getParam(g, "eta").x, 1.7f, 1e-6f);
  expectNear(getParam(g, "tint"), {0.9f, 1.0f, 0.95f}, "tint = base colour");

  // Rough transmission is rough glass with alpha = roughness^2; glTF's default roughness is 1.
  const Scene frosted = loadMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 1.45}}},
                                                      {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}},
                                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.9, 1.0, 1.0}},
                                                                {"roughnessFactor", 0.3}}}});
  const gpu::MaterialRecord& f = frosted.materials[0].record;
  EXPECT_EQ(f.model, modelId("ggx_dielectric"));
  EXPECT_NEAR(getParam(f, "alpha_x").x, 0.09f, 1e-6f);
  EXPECT_NEAR(getParam(f, "alpha_y").x, 0.09f, 1e-6f);
  EXPECT_NEAR(getParam(f, "eta").x, 1.45f, 1e-6f);
  expectNear(getParam(f, "tint"), {0.8f, 0.9f, 1.0f}, "tint = base colour");
  const Scene byDefault = loadMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}});
  EXPECT_EQ(byDefault.materials[0].record.model, modelId("ggx_dielectric"));
  EXPECT_NEAR(getParam(byDefault.materials[0].record, "alpha_x").x, 1.0f, 1e-6f);
  const Scene noInterface = loadMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 1.0}}},
                                                          {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}});
  EXPECT_EQ(noInterface.materials[0].record.model, modelId("glass")) << "ior 1: no interface, smooth or rough";

  // Partial transmission, and any with a volume, is openpbr's translucent base: the base colour tints what passes at
  // the surface, or KHR_materials_volume's attenuation is its volume.
  const Scene partial = loadMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}},
                                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1.0}},
                                                                {"metallicFactor", 0.0}}}});
  const gpu::MaterialRecord& half = partial.materials[0].record;
  EXPECT_EQ(half.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(half, "transmission_weight").x, 0.5f);
  EXPECT_FLOAT_EQ(getParam(half, "transmission_depth").x, 0.0f);
  expectNear(getParam(half, "transmission_color"), {0.9f, 0.8f, 0.7f}, "tinted by the base colour");
  const Scene absorbing = loadMaterial(
      {{"extensions", {{"KHR_materials_ior", {{"ior", 1.6}}}, {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                       {"KHR_materials_volume", {{"thicknessFactor", 0.2}, {"attenuationDistance", 0.5},
                                                 {"attenuationColor", {0.2, 0.6, 0.9}}}}}},
       {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.1}}}});
  const gpu::MaterialRecord& v = absorbing.materials[0].record;
  EXPECT_EQ(v.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(v, "transmission_weight").x, 1.0f);
  EXPECT_FLOAT_EQ(getParam(v, "transmission_depth").x, 0.5f);
  expectNear(getParam(v, "transmission_color"), {0.2f, 0.6f, 0.9f}, "the volume's attenuation colour");
  EXPECT_NEAR(getParam(v, "specular_ior").x, 1.6f, 1e-6f);
  const Scene clear = loadMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                                    {"KHR_materials_volume", {{"thicknessFactor", 1.0}}}}}});
  EXPECT_EQ(clear.materials[0].record.model, modelId("ggx_dielectric")) << "a volume that absorbs nothing is glass";
  for (const json& bad : {json{{"thicknessFactor", -1.0}}, json{{"attenuationDistance", 0.0}},
                          json{{"attenuationColor", {1.5, 0.0, 0.0}}}, json{{"attenuationColor", {0.5}}}}) {
    const std::string volumeError = materialError({{"name", "bad volume"}, {"extensions", {{"KHR_materials_volume", bad}}}});
    EXPECT_NE(volumeError.find("volume"), std::string::npos) << volumeError;
  }

  const std::string error = materialError({{"name", "gem"}, {"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}});
  EXPECT_NE(error.find("material 0 'gem': KHR_materials_ior.ior = 0.5 is outside [1, 10]"), std::string::npos) << error;
}

TEST(GltfMaterial, CoreFactorsOutOfRangeAreErrors) {
  const std::string error =
      materialError({{"name", "hot"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1.5, 0, 0, 1}}}}});
  EXPECT_NE(error.find("material 0 'hot': baseColorFactor[0] = 1.5 is outside [0, 1]"), std::string::npos) << error;
}

TEST(GltfMaterial, ExtrasWithoutAModelAdjustTheMappedMaterial) {
  const Scene scene = loadMaterial({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                                    {"extras", {{"raylab", {{"delta", 0.5}}}}}});
  EXPECT_EQ(scene.materials[0].record.model, modelId("gltf_pbr"));
  EXPECT_FLOAT_EQ(scene.materials[0].record.delta, 0.5f);
}

TEST(GltfMaterial, PrimitivesWithoutAMaterialShareADefaultGreyLambert) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.addNode({{"mesh", mesh}});
  b.addNode({{"mesh", mesh}, {"translation", {2, 0, 0}}});
  const Scene scene = b.load();
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_EQ(scene.materials[0].record.model, modelId("lambert"));
  expectNear(getParam(scene.materials[0].record, "rho_d"), glm::vec3(0.8f), "default grey");
}

// A quad with TEXCOORD_0 and one material per texture image.
GltfBuilder texturedScene(const std::vector<std::string>& images, const json& samplers, const json& textures) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.doc()["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2");
  for (const std::string& uri : images) b.doc()["images"].push_back({{"uri", uri}});
  b.doc()["samplers"] = samplers;
  b.doc()["textures"] = textures;
  for (std::size_t t = 0; t < textures.size(); ++t) {
    const int material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", t}}}}}});
    json primitive = b.doc()["meshes"][mesh]["primitives"][0];
    primitive["material"] = material;
    b.doc()["meshes"].push_back({{"primitives", {primitive}}});
    b.addNode({{"mesh", b.doc()["meshes"].size() - 1}});
  }
  return b;
}

TEST(GltfMaterial, BaseColourTexturesAreDecodedToRgbaWithTheirWrapModes) {
  const GltfBuilder b = texturedScene(
      {kPngRgb, kPngGrey16, kPngGreyAlpha},
      json::array({{{"wrapS", 33071}, {"wrapT", 33648}}, {{"wrapS", 33648}}}),
      json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 1}, {"sampler", 1}}, {{"source", 2}},
                   {{"source", 0}, {"sampler", 0}}}));
  const Scene scene = b.load();
  ASSERT_EQ(scene.textures.size(), 4u);
  for (std::size_t m = 0; m < 4; ++m) {
    ASSERT_EQ(scene.materials[m].record.textures, int(m));
    EXPECT_EQ(scene.materialTextures[m].refs[gpu::kTextureBaseColor].texture, int(m));
  }

  const Texture& rgb = scene.textures[0];
  EXPECT_EQ(rgb.width, 2u);
  EXPECT_EQ(rgb.height, 2u);
  EXPECT_EQ(rgb.rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}));
  EXPECT_EQ(rgb.wrapS, gpu::kWrapClamp);
  EXPECT_EQ(rgb.wrapT, gpu::kWrapMirror);

  const Texture& grey = scene.textures[1];
  EXPECT_TRUE(grey.rgba.empty());
  EXPECT_EQ(grey.rgba16, (std::vector<std::uint16_t>{0, 0, 0, 65535, 0x8080, 0x8080, 0x8080, 65535, 65535, 65535,
                                                     65535, 65535}))
      << "16 bits kept, grey expands to RGB";
  EXPECT_EQ(grey.wrapS, gpu::kWrapMirror);
  EXPECT_EQ(grey.wrapT, gpu::kWrapRepeat) << "glTF's default wrap";

  const Texture& greyAlpha = scene.textures[2];
  EXPECT_EQ(greyAlpha.rgba, (std::vector<std::uint8_t>{10, 10, 10, 20, 200, 200, 200, 250}));
  EXPECT_EQ(greyAlpha.wrapS, gpu::kWrapRepeat) << "no sampler: repeat";
}

// Each use of a texture with its UV set, KHR_texture_transform and scale; one image shared by every use is
// decoded once. The occlusion texture is checked and not used; an emissive texture is not read yet (warned).
TEST(GltfMaterial, EveryTextureUseIsReadWithItsUvSetTransformAndScale) {
  GltfBuilder b = texturedScene({kPngRgb}, json::array({{{"magFilter", 9728}}}), json::array({{{"source", 0}, {"sampler", 0}}}));
  b.doc()["meshes"][1]["primitives"][0]["attributes"]["TEXCOORD_1"] = b.addFloats({0, 0, 2, 0, 2, 2, 0, 2}, "VEC2");
  json& material = b.doc()["materials"][0];
  material["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {
      {"index", 0},
      {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 1.5707963267948966},
                                                 {"scale", {2.0, 3.0}}, {"texCoord", 1}}}}}};
  material["normalTexture"] = {{"index", 0}, {"scale", 0.5}};
  material["occlusionTexture"] = {{"index", 0}, {"strength", 0.3}};
  WarningCapture warnings;
  const Scene scene = b.load();
  ASSERT_EQ(scene.textures.size(), 1u) << "one image, decoded once for three uses";
  EXPECT_TRUE(scene.textures[0].nearest) << "magFilter NEAREST";
  ASSERT_EQ(scene.materials[0].record.textures, 0);
  const gpu::MaterialTextures& uses = scene.materialTextures[0];
  EXPECT_EQ(uses.refs[gpu::kTextureBaseColor].texture, 0);
  EXPECT_EQ(uses.refs[gpu::kTextureBaseColor].texCoord, 0u);
  const gpu::TextureRef& mr = uses.refs[gpu::kTextureMetallicRoughness];
  EXPECT_EQ(mr.texture, 0);
  EXPECT_EQ(mr.texCoord, 1u) << "the transform's texCoord overrides the textureInfo's";
  // T R S with a quarter turn: u' = 0 u + 3 v + 0.5, v' = -2 u + 0 v + 0.25.
  EXPECT_NEAR(mr.row0.x, 0.0f, 1e-6f);
  EXPECT_NEAR(mr.row0.y, 3.0f, 1e-6f);
  EXPECT_NEAR(mr.row0.z, 0.5f, 1e-6f);
  EXPECT_NEAR(mr.row1.x, -2.0f, 1e-6f);
  EXPECT_NEAR(mr.row1.y, 0.0f, 1e-6f);
  EXPECT_NEAR(mr.row1.z, 0.25f, 1e-6f);
  EXPECT_EQ(uses.refs[gpu::kTextureNormal].texture, 0);
  EXPECT_EQ(uses.refs[gpu::kTextureNormal].scale, 0.5f);
  EXPECT_EQ(uses.refs[gpu::kTextureEmissive].texture, -1);
  // The mesh keeps TEXCOORD_1 (read by the metallic-roughness texture) and gets tangents for the normal map.
  const Mesh& mesh = scene.meshes[scene.instances[0].mesh];
  EXPECT_EQ(mesh.uvs1.size(), 4u);
  ASSERT_EQ(mesh.tangents.size(), 4u);
  for (const glm::vec4& t : mesh.tangents) {
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
    EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f);
  }
  EXPECT_EQ(warnings.count("ignore"), 0) << "every use is read";
}

// KHR_materials_specular: the factors are gltf_pbr's specular and specular_color, its textures the uses that
// scale them; an out-of-range factor is an error naming the material, a colour above the model's range is used
// as its largest with a warning.
TEST(GltfMaterial, KhrMaterialsSpecularSetsTheDielectricsStrengthAndColour) {
  GltfBuilder b = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  b.doc()["extensionsUsed"] = {"KHR_materials_specular"};
  b.doc()["materials"][0]["extensions"]["KHR_materials_specular"] = {
      {"specularFactor", 0.25}, {"specularColorFactor", {0.5, 1.0, 2.0}},
      {"specularTexture", {{"index", 0}}}, {"specularColorTexture", {{"index", 0}, {"texCoord", 0}}}};
  WarningCapture warnings;
  const Scene scene = b.load();
  const gpu::MaterialRecord& record = scene.materials[0].record;
  expectNear(getParam(record, "specular"), glm::vec3(0.25f), "specular");
  expectNear(getParam(record, "specular_color"), glm::vec3(0.5f, 1.0f, 2.0f), "specular_color");
  ASSERT_GE(record.textures, 0);
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(record.textures)];
  EXPECT_EQ(uses.refs[gpu::kTextureSpecular].texture, 0);
  EXPECT_EQ(uses.refs[gpu::kTextureSpecularColor].texture, 0);
  EXPECT_EQ(warnings.count("KHR_materials_specular"), 0) << "read, not ignored";

  GltfBuilder bright = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  bright.doc()["materials"][0]["extensions"]["KHR_materials_specular"] = {{"specularColorFactor", {100.0, 1.0, 1.0}}};
  WarningCapture brightWarnings;
  expectNear(getParam(bright.load().materials[0].record, "specular_color"), glm::vec3(25.0f, 1.0f, 1.0f), "clamped");
  EXPECT_EQ(brightWarnings.count("specularColorFactor is above gltf_pbr's 25"), 1);

  for (const json& bad : {json{{"specularFactor", 1.5}}, json{{"specularColorFactor", {-1.0, 1.0, 1.0}}}}) {
    GltfBuilder broken = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
    broken.doc()["materials"][0]["extensions"]["KHR_materials_specular"] = bad;
    const std::string error = errorOf([&] { broken.load(); });
    EXPECT_NE(error.find("KHR_materials_specular.specular"), std::string::npos) << error;
    EXPECT_NE(error.find("material 0"), std::string::npos) << error;
  }
}

// KHR_materials_clearcoat maps the material onto openpbr: the core factors as its base, the extension's coat (index
// 1.5, no darkening) as its coat (docs/gltf.md, "Material extensions"). A factor of 0 leaves glTF's own BRDF.
TEST(GltfMaterial, KhrMaterialsClearcoatIsOpenPbrsCoat) {
  WarningCapture warnings;
  const Scene scene = loadMaterial({{"name", "lacquer"},
                                    {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.02, 0.01, 1.0}},
                                                              {"metallicFactor", 0.0}, {"roughnessFactor", 0.44}}},
                                    {"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.8},
                                                                                 {"clearcoatRoughnessFactor", 0.03}}},
                                                    {"KHR_materials_ior", {{"ior", 1.45}}}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("openpbr"));
  expectNear(getParam(r, "base_color"), {0.5f, 0.02f, 0.01f}, "base_color");
  EXPECT_FLOAT_EQ(getParam(r, "base_metalness").x, 0.0f);
  EXPECT_FLOAT_EQ(getParam(r, "specular_roughness").x, 0.44f);
  EXPECT_FLOAT_EQ(getParam(r, "specular_ior").x, 1.45f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_weight").x, 0.8f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_roughness").x, 0.03f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_ior").x, 1.5f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_darkening").x, 0.0f);
  EXPECT_EQ(warnings.count("KHR_materials_clearcoat"), 0) << "read, not ignored";

  const Scene uncoated = loadMaterial({{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.0}}}}}});
  EXPECT_EQ(uncoated.materials[0].record.model, modelId("gltf_pbr"));

  GltfBuilder textured = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  textured.doc()["materials"][0]["extensions"]["KHR_materials_clearcoat"] = {{"clearcoatFactor", 1.0},
                                                                              {"clearcoatTexture", {{"index", 0}}}};
  textured.doc()["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatRoughnessTexture"] = {{"index", 0}};
  textured.doc()["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatNormalTexture"] = {{"index", 0},
                                                                                                      {"scale", 0.5}};
  WarningCapture textureWarnings;
  const Scene coatTextures = textured.load();
  // The coat's textures scale coat_weight (R) and coat_roughness (G) of the openpbr material they were read for;
  // its normal map gives the coat's own normal (geometry_coat_normal_x and _y, set at each hit), with its scale.
  const gpu::MaterialRecord& coated = coatTextures.materials[0].record;
  ASSERT_GE(coated.textures, 0);
  const gpu::MaterialTextures& uses = coatTextures.materialTextures[std::size_t(coated.textures)];
  EXPECT_EQ(uses.layerModel, coated.model);
  EXPECT_GE(uses.refs[gpu::kTextureCoat].texture, 0);
  EXPECT_EQ(uses.refs[gpu::kTextureCoat].param, findParam(modelInfo(coated.model), "coat_weight")->slot);
  EXPECT_EQ(uses.refs[gpu::kTextureCoatRoughness].param, findParam(modelInfo(coated.model), "coat_roughness")->slot);
  EXPECT_TRUE(hasLayerTextures(coatTextures, coated));
  EXPECT_EQ(textureWarnings.count("clearcoatTexture"), 0) << "read";
  EXPECT_EQ(uses.refs[gpu::kTextureCoatNormal].param, findParam(modelInfo(coated.model), "geometry_coat_normal_x")->slot);
  EXPECT_GE(uses.refs[gpu::kTextureCoatNormal].texture, 0);
  EXPECT_FLOAT_EQ(uses.refs[gpu::kTextureCoatNormal].scale, 0.5f);
  EXPECT_EQ(textureWarnings.count("clearcoatNormalTexture"), 0) << "read";
  // KHR_materials_coat replaces the clear coat, its normal map included.
  textured.doc()["materials"][0]["extensions"]["KHR_materials_coat"] = {{"coatFactor", 1.0}};
  WarningCapture replacedWarnings;
  const Scene replaced = textured.load();
  const gpu::MaterialRecord& draft = replaced.materials[0].record;
  EXPECT_LT(replaced.materialTextures[std::size_t(draft.textures)].refs[gpu::kTextureCoatNormal].texture, 0);
  EXPECT_EQ(replacedWarnings.count("clearcoatNormalTexture (KHR_materials_coat replaces its layer)"), 1);
  textured.doc()["materials"][0]["extensions"]["KHR_materials_coat"]["coatNormalTexture"] = {{"index", 0}};
  const Scene ownNormal = textured.load();
  EXPECT_GE(ownNormal.materialTextures[std::size_t(ownNormal.materials[0].record.textures)]
                .refs[gpu::kTextureCoatNormal].texture, 0) << "the draft's own coatNormalTexture";
  textured.doc()["materials"][0]["extensions"].erase("KHR_materials_coat");
  // Without a coat (factor 0: glTF's own BRDF) the textures have nothing to scale: said, and nothing read.
  textured.doc()["materials"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatFactor"] = 0.0;
  WarningCapture absentWarnings;
  const Scene absent = textured.load();
  EXPECT_FALSE(hasLayerTextures(absent, absent.materials[0].record));
  EXPECT_EQ(absentWarnings.count("clearcoatRoughnessTexture (the material's model has no coat_roughness)"), 1);

  for (const json& bad : {json{{"clearcoatFactor", 1.5}}, json{{"clearcoatRoughnessFactor", -0.1}},
                          json{{"clearcoatFactor", "1"}}}) {
    // A value out of range names the material; a wrong type, caught by the schema, names its path.
    const std::string error = materialError({{"name", "bad coat"}, {"extensions", {{"KHR_materials_clearcoat", bad}}}});
    EXPECT_NE(error.find("KHR_materials_clearcoat.clearcoat"), std::string::npos) << error;
    EXPECT_TRUE(error.find("bad coat") != std::string::npos || error.find("materials[0]") != std::string::npos) << error;
  }
}

// KHR_materials_iridescence maps onto openpbr's thin film: the factor as its weight, the index, and the maximum
// thickness (no thickness texture) in micrometres. A factor of 0 leaves glTF's own BRDF.
TEST(GltfMaterial, KhrMaterialsIridescenceIsOpenPbrsThinFilm) {
  WarningCapture warnings;
  const Scene scene = loadMaterial({{"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.2}}},
                                    {"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.9},
                                                                                   {"iridescenceIor", 1.8},
                                                                                   {"iridescenceThicknessMaximum", 650.0}}}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(r, "base_metalness").x, 1.0f);
  EXPECT_FLOAT_EQ(getParam(r, "thin_film_weight").x, 0.9f);
  EXPECT_FLOAT_EQ(getParam(r, "thin_film_ior").x, 1.8f);
  EXPECT_FLOAT_EQ(getParam(r, "thin_film_thickness").x, 0.65f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_weight").x, 0.0f);
  EXPECT_EQ(warnings.count("KHR_materials_iridescence"), 0) << "read, not ignored";
  // The extension's defaults: index 1.3, 400 nm.
  const Scene defaults = loadMaterial({{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 1.0}}}}}});
  EXPECT_FLOAT_EQ(getParam(defaults.materials[0].record, "thin_film_ior").x, 1.3f);
  EXPECT_FLOAT_EQ(getParam(defaults.materials[0].record, "thin_film_thickness").x, 0.4f);
  const Scene none = loadMaterial({{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.0}}}}}});
  EXPECT_EQ(none.materials[0].record.model, modelId("gltf_pbr"));
  for (const json& bad : {json{{"iridescenceFactor", 1.5}}, json{{"iridescenceIor", 0.5}},
                          json{{"iridescenceThicknessMaximum", -1.0}}, json{{"iridescenceFactor", "1"}}}) {
    const std::string error = materialError({{"name", "bad film"}, {"extensions", {{"KHR_materials_iridescence", bad}}}});
    EXPECT_NE(error.find("iridescence"), std::string::npos) << error;
    EXPECT_TRUE(error.find("bad film") != std::string::npos || error.find("materials[0]") != std::string::npos) << error;
  }
}

// KHR_materials_sheen maps onto openpbr's fuzz: both layer as f_sheen + (1 - max(colour) E) f_base, so the weight is
// the colour's largest channel and the fuzz's colour the rest of it. A black sheen (the default) leaves glTF's BRDF.
TEST(GltfMaterial, KhrMaterialsSheenIsOpenPbrsFuzz) {
  WarningCapture warnings;
  const Scene scene = loadMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.1, 0.3, 1.0}}, {"metallicFactor", 0.0}}},
                                    {"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0.8, 0.4, 0.2}},
                                                                             {"sheenRoughnessFactor", 0.6}}}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(r, "fuzz_weight").x, 0.8f);
  EXPECT_EQ(getParam(r, "fuzz_color"), glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(getParam(r, "fuzz_roughness").x, 0.6f);
  EXPECT_EQ(getParam(r, "base_color"), glm::vec3(0.2f, 0.1f, 0.3f));
  EXPECT_EQ(warnings.count("KHR_materials_sheen"), 0) << "read, not ignored";
  const Scene none = loadMaterial({{"extensions", {{"KHR_materials_sheen", {{"sheenRoughnessFactor", 0.5}}}}}});
  EXPECT_EQ(none.materials[0].record.model, modelId("gltf_pbr"));
  // The sheen's colour texture (sRGB RGB) scales fuzz_color, its roughness texture (A) fuzz_roughness.
  GltfBuilder sheenTextured = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  sheenTextured.doc()["materials"][0]["extensions"]["KHR_materials_sheen"] = {
      {"sheenColorFactor", {1.0, 1.0, 1.0}}, {"sheenColorTexture", {{"index", 0}}}, {"sheenRoughnessTexture", {{"index", 0}}}};
  const Scene textured = sheenTextured.load();
  const gpu::MaterialRecord& fuzzy = textured.materials[0].record;
  ASSERT_GE(fuzzy.textures, 0);
  const gpu::MaterialTextures& sheenUses = textured.materialTextures[std::size_t(fuzzy.textures)];
  EXPECT_EQ(sheenUses.refs[gpu::kTextureSheenColor].param, findParam(modelInfo(fuzzy.model), "fuzz_color")->slot);
  EXPECT_EQ(sheenUses.refs[gpu::kTextureSheenRoughness].param, findParam(modelInfo(fuzzy.model), "fuzz_roughness")->slot);
  EXPECT_EQ(warnings.count("sheenColorTexture"), 0) << "read";
  for (const json& bad : {json{{"sheenColorFactor", {1.5, 0.0, 0.0}}}, json{{"sheenRoughnessFactor", -0.1}},
                          json{{"sheenColorFactor", {0.5, 0.5}}}, json{{"sheenRoughnessFactor", "1"}}}) {
    const std::string error = materialError({{"name", "bad sheen"}, {"extensions", {{"KHR_materials_sheen", bad}}}});
    EXPECT_NE(error.find("sheen"), std::string::npos) << error;
    EXPECT_TRUE(error.find("bad sheen") != std::string::npos || error.find("materials[0]") != std::string::npos) << error;
  }
}

// The OpenPBR-aligned drafts name openpbr's own parameters: KHR_materials_coat (over the clear coat where both
// appear), KHR_materials_fuzz (over the sheen), KHR_materials_diffuse_roughness.
TEST(GltfMaterial, TheOpenPbrAlignedDraftsMapOntoTheirOwnParameters) {
  WarningCapture warnings;
  const Scene scene = loadMaterial(
      {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
       {"extensions", {{"KHR_materials_coat", {{"coatFactor", 0.8}, {"coatRoughnessFactor", 0.2}, {"coatIor", 1.4},
                                               {"coatColorFactor", {0.9, 0.8, 0.7}}, {"coatDarkeningFactor", 0.5}}},
                       {"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}},
                       {"KHR_materials_fuzz", {{"fuzzFactor", 0.6}, {"fuzzColorFactor", {0.2, 0.4, 0.6}},
                                               {"fuzzRoughnessFactor", 0.7}}},
                       {"KHR_materials_sheen", {{"sheenColorFactor", {1.0, 1.0, 1.0}}}},
                       {"KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", 0.9}}}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(r, "coat_weight").x, 0.8f) << "the draft coat, not the clear coat";
  EXPECT_FLOAT_EQ(getParam(r, "coat_roughness").x, 0.2f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_ior").x, 1.4f);
  EXPECT_FLOAT_EQ(getParam(r, "coat_darkening").x, 0.5f);
  expectNear(getParam(r, "coat_color"), {0.9f, 0.8f, 0.7f}, "coat colour");
  EXPECT_FLOAT_EQ(getParam(r, "fuzz_weight").x, 0.6f) << "the fuzz, not the sheen";
  expectNear(getParam(r, "fuzz_color"), {0.2f, 0.4f, 0.6f}, "fuzz colour");
  EXPECT_FLOAT_EQ(getParam(r, "fuzz_roughness").x, 0.7f);
  EXPECT_FLOAT_EQ(getParam(r, "base_diffuse_roughness").x, 0.9f);
  // KHR_materials_anisotropy: the ratio alpha_b / alpha_t of glTF's stretch, mix(alpha, 1, s^2) against alpha.
  const Scene brushed = loadMaterial({{"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.5}}},
                                      {"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6},
                                                                                    {"anisotropyRotation", 0.3}}}}}});
  const gpu::MaterialRecord& b = brushed.materials[0].record;
  EXPECT_EQ(b.model, modelId("openpbr"));
  EXPECT_NEAR(getParam(b, "specular_roughness_anisotropy").x, 1.0f - 0.25f / (0.25f + 0.75f * 0.36f), 1e-6f);
  EXPECT_EQ(warnings.count("anisotropyRotation"), 0) << "read, not ignored";
  ASSERT_GE(b.textures, 0) << "a rotation alone gives the material its texture record, which holds it";
  EXPECT_FLOAT_EQ(brushed.materialTextures[std::size_t(b.textures)].anisotropyRotation, 0.3f);
  EXPECT_EQ(brushed.materialTextures[std::size_t(b.textures)].layerModel, b.model);
  EXPECT_TRUE(hasLayerTextures(brushed, b));
  // A rotation of more than a turn is the same direction.
  const Scene turns = loadMaterial({{"pbrMetallicRoughness", {{"metallicFactor", 1.0}}},
                                    {"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6},
                                                                                  {"anisotropyRotation", 0.3 + 8.0 * std::numbers::pi}}}}}});
  EXPECT_NEAR(turns.materialTextures[std::size_t(turns.materials[0].record.textures)].anisotropyRotation, 0.3f, 1e-5f);
  // The texture: its slot names the anisotropy's parameter and holds the factor's strength (hit_common.glsl).
  GltfBuilder texturedBuilder = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  texturedBuilder.doc()["materials"][0]["extensions"] = {
      {"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyTexture", {{"index", 0}}}}}};
  const Scene anisotropyTextured = texturedBuilder.load();
  const gpu::MaterialRecord& at = anisotropyTextured.materials[0].record;
  ASSERT_GE(at.textures, 0);
  const gpu::TextureRef& direction = anisotropyTextured.materialTextures[std::size_t(at.textures)].refs[gpu::kTextureAnisotropy];
  EXPECT_GE(direction.texture, 0);
  EXPECT_EQ(direction.param, findParam(modelInfo(at.model), "specular_roughness_anisotropy")->slot);
  EXPECT_FLOAT_EQ(direction.scale, 0.6f);
  for (const json& bad : {json{{"KHR_materials_coat", {{"coatFactor", 2.0}}}},
                          json{{"KHR_materials_fuzz", {{"fuzzColorFactor", {0.5, -0.1, 0.5}}}}},
                          json{{"KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", "rough"}}}}}) {
    const std::string error = materialError({{"name", "bad draft"}, {"extensions", bad}});
    EXPECT_NE(error.find("KHR_materials_"), std::string::npos) << error;
  }
}

// KHR_materials_diffuse_transmission: the diffuse lobe's mix of the base colour's BRDF and the transmission colour's
// BTDF is openpbr's thin-walled subsurface that passes all its light; with KHR_materials_volume its light is
// attenuated over the volume's thickness (the Sample Viewer's reading), and with a specular transmission as well the
// volume is that transmission's and the diffuse one is not applied (one warning).
TEST(GltfMaterial, KhrMaterialsDiffuseTransmissionIsAThinSubsurfaceSheetThatPassesItsLight) {
  WarningCapture warnings;
  const json extension = {{"diffuseTransmissionFactor", 0.4}, {"diffuseTransmissionColorFactor", {1.0, 0.5, 0.2}}};
  const Scene scene = loadMaterial({{"extensions", {{"KHR_materials_diffuse_transmission", extension}}}});
  const gpu::MaterialRecord& r = scene.materials[0].record;
  EXPECT_EQ(r.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(r, "geometry_thin_walled").x, 1.0f);
  EXPECT_FLOAT_EQ(getParam(r, "subsurface_weight").x, 0.4f);
  expectNear(getParam(r, "subsurface_color"), {1.0f, 0.5f, 0.2f}, "transmission colour");
  EXPECT_FLOAT_EQ(getParam(r, "subsurface_scatter_anisotropy").x, 1.0f);
  EXPECT_EQ(warnings.count("KHR_materials_diffuse_transmission"), 0) << "read, not ignored";
  const Scene withVolume = loadMaterial(
      {{"extensions", {{"KHR_materials_diffuse_transmission", extension},
                       {"KHR_materials_transmission", {{"transmissionFactor", 0.5}}},
                       {"KHR_materials_volume", {{"thicknessFactor", 1.0}, {"attenuationDistance", 2.0}}}}}});
  EXPECT_FLOAT_EQ(getParam(withVolume.materials[0].record, "geometry_thin_walled").x, 0.0f);
  EXPECT_EQ(warnings.count("with KHR_materials_transmission and KHR_materials_volume it is not applied"), 1);
  // attenuationColor^(thicknessFactor / attenuationDistance) = (0.25, 0.64, 1)^(1/2).
  const Scene translucent = loadMaterial(
      {{"extensions", {{"KHR_materials_diffuse_transmission", extension},
                       {"KHR_materials_volume", {{"thicknessFactor", 1.0}, {"attenuationDistance", 2.0},
                                                 {"attenuationColor", {0.25, 0.64, 1.0}}}}}}});
  const gpu::MaterialRecord& v = translucent.materials[0].record;
  EXPECT_FLOAT_EQ(getParam(v, "geometry_thin_walled").x, 1.0f);
  EXPECT_FLOAT_EQ(getParam(v, "transmission_weight").x, 0.0f) << "no volume of its own: no medium to enter";
  expectNear(getParam(v, "subsurface_color"), {0.5f, 0.4f, 0.2f}, "transmission colour through half a distance");
  const Scene none = loadMaterial({{"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.0}}}}}});
  EXPECT_EQ(none.materials[0].record.model, modelId("gltf_pbr"));
  // Its textures: A scales subsurface_weight, the sRGB RGB subsurface_color.
  GltfBuilder builder = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  builder.doc()["materials"][0]["extensions"] = {
      {"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.4},
                                              {"diffuseTransmissionTexture", {{"index", 0}}},
                                              {"diffuseTransmissionColorTexture", {{"index", 0}}}}}};
  const Scene textured = builder.load();
  const gpu::MaterialRecord& t = textured.materials[0].record;
  ASSERT_GE(t.textures, 0);
  const gpu::MaterialTextures& uses = textured.materialTextures[std::size_t(t.textures)];
  EXPECT_EQ(uses.refs[gpu::kTextureDiffuseTransmission].param, findParam(modelInfo(t.model), "subsurface_weight")->slot);
  EXPECT_EQ(uses.refs[gpu::kTextureDiffuseTransmissionColor].param, findParam(modelInfo(t.model), "subsurface_color")->slot);
  for (const json& bad : {json{{"diffuseTransmissionFactor", 1.5}}, json{{"diffuseTransmissionColorFactor", {0.5, 0.5}}}}) {
    const std::string error = materialError({{"name", "bad leaf"}, {"extensions", {{"KHR_materials_diffuse_transmission", bad}}}});
    EXPECT_NE(error.find("KHR_materials_diffuse_transmission"), std::string::npos) << error;
  }
}

// KHR_materials_dispersion (dispersion = 20 / V_d) onto openpbr's V = abbe_number / scale: scale = dispersion with
// abbe_number 20 up to 1, then abbe_number = 20 / dispersion. It builds on the volume: a clear gem (a thickness and no
// attenuation) becomes openpbr rather than glass, a surface without a thickness is thin and does not disperse (one
// warning), and without transmission it is neutral.
TEST(GltfMaterial, KhrMaterialsDispersionSetsTheAbbeNumberOfTheVolume) {
  WarningCapture warnings;
  const auto gem = [](double dispersion) {
    return json{{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                {"KHR_materials_ior", {{"ior", 2.4}}},
                                {"KHR_materials_volume", {{"thicknessFactor", 1.0}}},
                                {"KHR_materials_dispersion", {{"dispersion", dispersion}}}}},
                {"pbrMetallicRoughness", {{"roughnessFactor", 0.0}}}};
  };
  const gpu::MaterialRecord diamond = loadMaterial(gem(0.36)).materials[0].record;  // V_d 55
  EXPECT_EQ(diamond.model, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(diamond, "transmission_weight").x, 1.0f);
  EXPECT_FLOAT_EQ(getParam(diamond, "specular_ior").x, 2.4f);
  EXPECT_FLOAT_EQ(getParam(diamond, "transmission_dispersion_scale").x, 0.36f);
  EXPECT_FLOAT_EQ(getParam(diamond, "transmission_dispersion_abbe_number").x, 20.0f);
  const gpu::MaterialRecord rutile = loadMaterial(gem(2.04)).materials[0].record;  // V_d 9.8
  EXPECT_FLOAT_EQ(getParam(rutile, "transmission_dispersion_scale").x, 1.0f);
  EXPECT_NEAR(getParam(rutile, "transmission_dispersion_abbe_number").x, 20.0f / 2.04f, 1e-5f);
  EXPECT_EQ(warnings.count("KHR_materials_dispersion"), 0) << "read, not ignored";
  EXPECT_EQ(loadMaterial(gem(0.0)).materials[0].record.model, modelId("glass")) << "0: no dispersion, the clear gem";
  const gpu::MaterialRecord extreme = loadMaterial(gem(50.0)).materials[0].record;
  EXPECT_FLOAT_EQ(getParam(extreme, "transmission_dispersion_abbe_number").x, 1.0f);
  EXPECT_EQ(warnings.count("is used as openpbr's least Abbe number"), 1);
  json thin = gem(0.5);
  thin["extensions"].erase("KHR_materials_volume");
  thin["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 0.5;
  EXPECT_FLOAT_EQ(getParam(loadMaterial(thin).materials[0].record, "transmission_dispersion_scale").x, 0.0f);
  EXPECT_EQ(warnings.count("without KHR_materials_volume's thickness the surface is thin"), 1);
  const json opaque = {{"extensions", {{"KHR_materials_dispersion", {{"dispersion", 1.0}}}}}};
  EXPECT_EQ(loadMaterial(opaque).materials[0].record.model, modelId("gltf_pbr")) << "nothing to disperse";
  for (const json& bad : {json{{"dispersion", -0.1}}, json{{"dispersion", "high"}}}) {
    const std::string error = materialError({{"name", "bad gem"}, {"extensions", {{"KHR_materials_dispersion", bad}}}});
    EXPECT_NE(error.find("KHR_materials_dispersion"), std::string::npos) << error;
  }
}

// The drafts' textures in their texts' channels (coat R weight, G roughness, sRGB colour; fuzz R weight, sRGB colour,
// A roughness; diffuse roughness R) scale the parameters their factors set, and where a draft replaces a ratified
// extension (coat over clear coat, fuzz over sheen) the replaced one's textures are reported and not read.
TEST(GltfMaterial, TheDraftsTexturesScaleTheirParametersAndReplaceTheRatifiedOnes) {
  WarningCapture warnings;
  GltfBuilder builder = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  const json texture = {{"index", 0}};
  builder.doc()["materials"][0]["extensions"] = {
      {"KHR_materials_coat", {{"coatFactor", 0.8}, {"coatTexture", texture}, {"coatRoughnessFactor", 0.3},
                              {"coatRoughnessTexture", texture}, {"coatColorTexture", texture},
                              {"coatAnisotropyStrength", 0.5}}},
      {"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatTexture", texture}}},
      {"KHR_materials_fuzz", {{"fuzzFactor", 0.6}, {"fuzzTexture", texture}, {"fuzzColorTexture", texture},
                              {"fuzzRoughnessTexture", texture}}},
      {"KHR_materials_sheen", {{"sheenColorFactor", {1.0, 1.0, 1.0}}, {"sheenRoughnessTexture", texture}}},
      {"KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", 0.9}, {"diffuseRoughnessTexture", texture}}}};
  const Scene scene = builder.load();
  const gpu::MaterialRecord& r = scene.materials[0].record;
  ASSERT_EQ(r.model, modelId("openpbr"));
  ASSERT_GE(r.textures, 0);
  const gpu::MaterialTextures& uses = scene.materialTextures[std::size_t(r.textures)];
  EXPECT_EQ(uses.layerModel, r.model);
  const ModelInfo& openpbr = modelInfo(r.model);
  for (const auto& [use, param] : std::vector<std::pair<std::uint32_t, const char*>>{
           {gpu::kTextureCoat, "coat_weight"}, {gpu::kTextureCoatRoughness, "coat_roughness"},
           {gpu::kTextureCoatColor, "coat_color"}, {gpu::kTextureFuzz, "fuzz_weight"},
           {gpu::kTextureSheenColor, "fuzz_color"}, {gpu::kTextureSheenRoughness, "fuzz_roughness"},
           {gpu::kTextureDiffuseRoughness, "base_diffuse_roughness"}}) {
    EXPECT_GE(uses.refs[use].texture, 0) << param;
    EXPECT_EQ(uses.refs[use].param, findParam(openpbr, param)->slot) << param;
    EXPECT_EQ(uses.refs[use].scale, 0.0f) << param;
  }
  EXPECT_EQ(warnings.count("clearcoatTexture (KHR_materials_coat replaces"), 1);
  EXPECT_EQ(warnings.count("sheenRoughnessTexture (KHR_materials_fuzz replaces"), 1);
  for (const char* read : {"coatTexture", "coatColorTexture", "fuzzTexture", "diffuseRoughnessTexture"}) {
    EXPECT_EQ(warnings.count(std::string("KHR_materials_") + (read[0] == 'c' ? "coat." : read[0] == 'f' ? "fuzz." : "diffuse_roughness.") + read), 0)
        << read << " is read, not ignored";
  }
  // coatAnisotropyStrength as KHR_materials_anisotropy's strength, on the coat's roughness.
  EXPECT_NEAR(getParam(r, "coat_roughness_anisotropy").x, 1.0f - 0.09f / (0.09f + 0.91f * 0.25f), 1e-6f);
  EXPECT_FLOAT_EQ(getParam(r, "geometry_coat_tangent_angle").x, 0.0f) << "no rotation: along the tangent";
}

// coatAnisotropyRotation turns the coat's tangent: from the shading frame, which the base's anisotropyRotation has
// already turned, by the difference of the two, wrapped to [-pi, pi].
TEST(GltfMaterial, TheCoatsAnisotropyRotationTurnsItsTangentFromTheBases) {
  const auto angleOf = [](double coatRotation, double baseStrength, double baseRotation) {
    const json material = {
        {"extensions", {{"KHR_materials_coat", {{"coatFactor", 1.0}, {"coatRoughnessFactor", 0.3},
                                                {"coatAnisotropyStrength", 0.5}, {"coatAnisotropyRotation", coatRotation}}},
                        {"KHR_materials_anisotropy", {{"anisotropyStrength", baseStrength},
                                                      {"anisotropyRotation", baseRotation}}}}}};
    return double(getParam(loadMaterial(material).materials[0].record, "geometry_coat_tangent_angle").x);
  };
  WarningCapture warnings;
  EXPECT_NEAR(angleOf(1.0, 0.0, 0.4), 1.0, 1e-6) << "the base without anisotropy does not turn its frame";
  EXPECT_NEAR(angleOf(1.0, 0.5, 0.4), 0.6, 1e-6);
  EXPECT_NEAR(angleOf(7.0, 0.0, 0.0), 7.0 - 2.0 * std::numbers::pi, 1e-6);
  EXPECT_NEAR(angleOf(-3.0, 0.5, 3.0), -6.0 + 2.0 * std::numbers::pi, 1e-6);
  EXPECT_EQ(warnings.count("coatAnisotropyRotation"), 0) << "read, not ignored";
}

// KHR_materials_coat's coatAnisotropyTexture: read where the coat is anisotropic, its use packing the slots of the
// coat's ratio, roughness and tangent angle, its strength the factor; kept without a texture where only the base's
// anisotropyTexture turns the frame (the kernel takes that turn back off the coat's angle); not read without the
// coat's anisotropy. The rendered answer is tests/image/texture_render_test.cpp's.
TEST(GltfMaterial, TheCoatsAnisotropyTextureTurnsAndScalesTheCoatsStretch) {
  WarningCapture warnings;
  const auto load = [](const json& coat, const json& anisotropy) {
    GltfBuilder builder = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
    builder.doc()["materials"][0]["extensions"] = {{"KHR_materials_coat", coat}};
    if (!anisotropy.is_null()) builder.doc()["materials"][0]["extensions"]["KHR_materials_anisotropy"] = anisotropy;
    return builder.load();
  };
  const json texture = {{"index", 0}};
  const Scene scene = load({{"coatFactor", 1.0}, {"coatRoughnessFactor", 0.3}, {"coatAnisotropyStrength", 0.5},
                            {"coatAnisotropyTexture", texture}},
                           nullptr);
  const gpu::MaterialRecord& r = scene.materials[0].record;
  const ModelInfo& openpbr = modelInfo(r.model);
  ASSERT_GE(r.textures, 0);
  const gpu::TextureRef& ref = scene.materialTextures[std::size_t(r.textures)].refs[gpu::kTextureCoatAnisotropy];
  EXPECT_GE(ref.texture, 0);
  EXPECT_EQ(ref.param, findParam(openpbr, "coat_roughness_anisotropy")->slot |
                           findParam(openpbr, "coat_roughness")->slot << 8u |
                           findParam(openpbr, "geometry_coat_tangent_angle")->slot << 16u);
  EXPECT_FLOAT_EQ(ref.scale, 0.5f);
  EXPECT_EQ(warnings.count("coatAnisotropyTexture"), 0) << "read, not ignored";

  const Scene baseTurns = load({{"coatFactor", 1.0}, {"coatAnisotropyStrength", 0.5}},
                               {{"anisotropyStrength", 0.5}, {"anisotropyTexture", texture}});
  const gpu::TextureRef& kept =
      baseTurns.materialTextures[std::size_t(baseTurns.materials[0].record.textures)].refs[gpu::kTextureCoatAnisotropy];
  EXPECT_LT(kept.texture, 0);
  EXPECT_NE(kept.param, 0u) << "the coat's angle loses the base texel's turn";

  const Scene isotropic = load({{"coatFactor", 1.0}, {"coatAnisotropyTexture", texture}}, nullptr);
  EXPECT_EQ(warnings.count("coatAnisotropyTexture (the coat's anisotropy is absent)"), 1);
  const gpu::MaterialRecord& i = isotropic.materials[0].record;
  EXPECT_TRUE(i.textures < 0 ||
              isotropic.materialTextures[std::size_t(i.textures)].refs[gpu::kTextureCoatAnisotropy].param == 0u);
}

// Each layered extension at its neutral value is no layer: beside a clear coat (which makes the material openpbr
// either way), adding it leaves every parameter as without it. The non-neutral answers are tested above (the
// mapping) and in tests/cpu/openpbr_test.cpp, fuzz_test.cpp and the path integrator's Beer-Lambert test (the
// result).
TEST(GltfMaterial, EveryLayeredExtensionAtItsNeutralValueIsNoLayer) {
  const json base = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.3, 0.2, 1.0}}, {"metallicFactor", 0.0},
                                               {"roughnessFactor", 0.4}}}};
  const auto withExtensions = [&](const json& extensions) {
    json material = base;
    material["extensions"] = extensions;
    material["extensions"]["KHR_materials_clearcoat"] = {{"clearcoatFactor", 1.0}};
    return loadMaterial(material).materials[0].record;
  };
  const gpu::MaterialRecord without = withExtensions(json::object());
  ASSERT_EQ(without.model, modelId("openpbr"));
  const std::vector<std::pair<std::string, json>> neutral = {
      {"KHR_materials_sheen", {{"sheenColorFactor", {0.0, 0.0, 0.0}}, {"sheenRoughnessFactor", 0.5}}},
      {"KHR_materials_iridescence", {{"iridescenceFactor", 0.0}}},
      {"KHR_materials_transmission", {{"transmissionFactor", 0.0}}},
      {"KHR_materials_volume", {{"thicknessFactor", 0.0}, {"attenuationDistance", 1.0}}},
      {"KHR_materials_anisotropy", {{"anisotropyStrength", 0.0}}},
      {"KHR_materials_fuzz", {{"fuzzFactor", 0.0}}},
      {"KHR_materials_diffuse_roughness", {{"diffuseRoughnessFactor", 0.0}}},
  };
  const ModelInfo& openpbr = modelInfo(without.model);
  for (const auto& [name, values] : neutral) {
    const gpu::MaterialRecord with = withExtensions(json{{name, values}});
    ASSERT_EQ(with.model, without.model) << name;
    for (const ParamInfo& p : openpbr.params) {
      EXPECT_EQ(getParam(with, p.name), getParam(without, p.name)) << name << ": " << p.name;
    }
    EXPECT_EQ(with.emission, without.emission) << name;
  }
}

// glTF 3.9.3: the emissive texture is multiplied by emissiveFactor, whose default is zero.
TEST(GltfMaterial, AnEmissiveTextureMultipliesTheFactorAndIsSkippedUnderAZeroOne) {
  GltfBuilder lit = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  lit.doc()["materials"][0]["emissiveTexture"] = {{"index", 0}, {"texCoord", 0}};
  lit.doc()["materials"][0]["emissiveFactor"] = {1.0, 0.5, 0.25};
  WarningCapture warnings;
  const Scene scene = lit.load();
  const gpu::MaterialRecord& record = scene.materials[0].record;
  EXPECT_EQ(record.emission, glm::vec3(1.0f, 0.5f, 0.25f));
  ASSERT_GE(record.textures, 0);
  EXPECT_EQ(scene.materialTextures[std::size_t(record.textures)].refs[gpu::kTextureEmissive].texture, 0);
  EXPECT_EQ(warnings.count("emissive"), 0);
  EXPECT_TRUE(scene.lights.empty()) << "an emitter replaces the default light";

  GltfBuilder dark = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  dark.doc()["materials"][0]["emissiveTexture"] = {{"index", 0}};
  dark.doc()["materials"][0]["pbrMetallicRoughness"].erase("baseColorTexture");
  const Scene unlit = dark.load();
  EXPECT_EQ(unlit.materials[0].record.emission, glm::vec3(0.0f));
  EXPECT_TRUE(unlit.textures.empty()) << "a texture nothing reads is not decoded";
}

TEST(GltfMaterial, TextureTransformsAndScalesThatAreNotFiniteAreErrorsNamingTheMaterial) {
  for (const json& bad : {json{{"index", 0}, {"scale", 1e40}},
                          json{{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", 1e39}}}}}}}) {
    GltfBuilder b = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
    b.doc()["materials"][0]["normalTexture"] = bad;
    const std::string error = errorOf([&] { b.load(); });
    EXPECT_NE(error.find("material 0"), std::string::npos) << "[" << error << "]";
    EXPECT_NE(error.find("normalTexture"), std::string::npos) << error;
    EXPECT_NE(error.find("not finite"), std::string::npos) << error;
  }
}

// glTF 3.9.4: MASK with its cutoff and BLEND are read with baseColorFactor's alpha; a material with alpha gets
// a MaterialTextures record even without textures; a bad mode or cutoff is an error naming the material.
TEST(GltfMaterial, AlphaModesAreReadAndBadOnesRefused) {
  GltfBuilder b = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
  b.doc()["materials"][0]["alphaMode"] = "MASK";
  b.doc()["materials"][0]["alphaCutoff"] = 0.3;
  b.doc()["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 0.8};
  b.doc()["materials"].push_back({{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.4}}}}});
  b.doc()["materials"].push_back({{"alphaMode", "OPAQUE"}});
  WarningCapture warnings;
  const Scene scene = b.load();
  ASSERT_GE(scene.materials[0].record.textures, 0);
  const gpu::MaterialTextures& mask = scene.materialTextures[std::size_t(scene.materials[0].record.textures)];
  EXPECT_EQ(mask.alphaMode, gpu::kAlphaMask);
  EXPECT_FLOAT_EQ(mask.alphaCutoff, 0.3f);
  EXPECT_FLOAT_EQ(mask.alpha, 0.8f);
  EXPECT_EQ(mask.refs[gpu::kTextureBaseColor].texture, 0);
  ASSERT_GE(scene.materials[1].record.textures, 0) << "alpha without a texture still needs the record";
  const gpu::MaterialTextures& blend = scene.materialTextures[std::size_t(scene.materials[1].record.textures)];
  EXPECT_EQ(blend.alphaMode, gpu::kAlphaBlend);
  EXPECT_FLOAT_EQ(blend.alpha, 0.4f);
  EXPECT_EQ(scene.materials[2].record.textures, -1) << "opaque and untextured: nothing to read";
  EXPECT_TRUE(hasAlpha(scene, scene.materials[0].record));
  EXPECT_FALSE(hasAlpha(scene, scene.materials[2].record));
  EXPECT_EQ(warnings.count("alpha"), 0);

  for (const auto& [property, value, expected] :
       {std::tuple<const char*, json, const char*>{"alphaCutoff", -0.5, "alphaCutoff = -0.5"},
        {"alphaMode", "CUTOUT", "alphaMode \"CUTOUT\" is not OPAQUE, MASK or BLEND"},
        {"alphaMode", "", "alphaMode \"\" is not OPAQUE, MASK or BLEND"}}) {
    GltfBuilder bad = texturedScene({kPngRgb}, json::array(), json::array({{{"source", 0}}}));
    bad.doc()["materials"][0]["alphaMode"] = "MASK";
    bad.doc()["materials"][0][property] = value;
    const std::string error = errorOf([&] { bad.load(); });
    EXPECT_NE(error.find("material 0"), std::string::npos) << error;
    EXPECT_NE(error.find(expected), std::string::npos) << error;
  }
}

TEST(GltfMaterial, AnInvalidWrapModeIsAnErrorNamingTheSampler) {
  const GltfBuilder b = texturedScene({kPngRgb}, json::array({{{"name", "odd"}, {"wrapS", 1234}}}),
                                      json::array({{{"source", 0}, {"sampler", 0}}}));
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: sampler 0 'odd' wrapS: wrap mode 1234"), std::string::npos) << error;
}

TEST(GltfMaterial, AnUndecodableImageIsAnError) {
  const GltfBuilder b = texturedScene({"data:image/png;base64,AAAA"}, json::array(), json::array({{{"source", 0}}}));
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: "), std::string::npos) << error;
  EXPECT_NE(error.find("image"), std::string::npos) << error;
}

// emissiveFactor x KHR_materials_emissive_strength is the emitted radiance; bad values name the material.
TEST(GltfMaterial, EmissionIsTheFactorTimesTheStrength) {
  GltfBuilder b;
  const int material = b.addMaterial({{"name", "lamp"},
                                      {"emissiveFactor", {1.0, 0.5, 0.25}},
                                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
  b.doc()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  b.addNode({{"mesh", b.addQuad(material)}});
  const Scene scene = b.load();
  EXPECT_EQ(scene.materials[0].record.emission, glm::vec3(4.0f, 2.0f, 1.0f));

  for (const json& strength : {json(-1.0), json(1e30)}) {
    GltfBuilder bad;
    const int m = bad.addMaterial({{"emissiveFactor", {1.0, 1.0, 1.0}},
                                   {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}});
    bad.addNode({{"mesh", bad.addQuad(m)}});
    const std::string error = errorOf([&] { bad.load(); });
    EXPECT_NE(error.find("test: material 0"), std::string::npos) << error;
    EXPECT_NE(error.find("emissive"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace raylab::test
