// The comparison's window-free logic: the MATERIAL=MODEL[:k=v,...] text of --compare, --material and the script,
// the script's comparison events, the mouse over the image (divider drags that keep the camera still, clicks,
// hovering), and the lobe's directions and albedo curve.
#include <gtest/gtest.h>

#include <cmath>

#include "brdf_eval/lobe.h"
#include "brdf_params/material_params.h"
#include "scene/scene.h"
#include "shared/features.h"
#include "util/error.h"
#include "view_logic/compare_spec.h"
#include "view_logic/pointer.h"
#include "view_logic/scene_edits.h"
#include "view_logic/script.h"

namespace raylab::test {
namespace {

Scene twoMaterials() {
  Scene scene;
  scene.materials = {{"ground", lambertMaterial(glm::vec3(0.5f))}, {"red plastic", lambertMaterial(glm::vec3(0.6f, 0.1f, 0.1f), 0.25f)}};
  return scene;
}

std::string usageError(const std::string& text) {
  try {
    parseCompareSpec(text, twoMaterials(), "--compare");
  } catch (const Error& error) {
    EXPECT_EQ(error.exitCode(), kExitUsage) << text;
    return error.what();
  }
  ADD_FAILURE() << "'" << text << "' was accepted";
  return "";
}

TEST(CompareSpecTest, SwitchesOneMaterialToAModelWithParametersOverItsDefaults) {
  const CompareSpec spec = parseCompareSpec("red plastic=ward:rho_d=0.2/0.5/0.2,alpha_x=0.3", twoMaterials(), "x");
  EXPECT_EQ(spec.material, 1u);
  EXPECT_EQ(spec.record.model, std::uint32_t(modelId("ward")));
  EXPECT_EQ(getParam(spec.record, "rho_d"), glm::vec3(0.2f, 0.5f, 0.2f));
  EXPECT_EQ(getParam(spec.record, "alpha_x"), glm::vec3(0.3f));
  EXPECT_EQ(getParam(spec.record, "alpha_y"), getParam(defaultRecord(modelId("ward")), "alpha_y"));
  EXPECT_EQ(spec.record.delta, 0.25f) << "the mirror weight is the material's, not the model's";
  EXPECT_EQ(describeRecord(spec.record).substr(0, 5), "ward ");
  // The model alone: its defaults.
  EXPECT_EQ(parseCompareSpec("ground=phong", twoMaterials(), "x").record.model, std::uint32_t(modelId("phong")));
}

TEST(CompareSpecTest, MistakesListWhatExists) {
  EXPECT_NE(usageError("nosuch=ward").find("'ground', 'red plastic'"), std::string::npos);
  EXPECT_NE(usageError("ground=wardish").find("lambert, phong"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:beta=2").find("alpha_x"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:alpha_x=-1").find("alpha_x"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:alpha_x=inf").find("expected a number"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:rho_d=1/2").find("r/g/b"), std::string::npos);
  EXPECT_NE(usageError("ground").find("MATERIAL=MODEL"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:alpha_x").find("name=value"), std::string::npos);
  EXPECT_NE(usageError("").find("empty"), std::string::npos);
  EXPECT_NE(usageError("ground=ward:alpha_x=0.1;alpha_x=0.2").find("given twice"), std::string::npos);
}

// One grammar of parameter lists everywhere: ',' or ';' between entries; "MATERIAL=MODEL;k=v" is read as meant
// (it used to look for a material named "red plastic=ward;alpha_x").
TEST(CompareSpecTest, ParameterListsTakeCommasOrSemicolons) {
  const glm::vec3 alphas(0.3f, 0.1f, 0.0f);
  for (const char* text : {"red plastic=ward:alpha_x=0.3,alpha_y=0.1", "red plastic=ward:alpha_x=0.3;alpha_y=0.1",
                           "red plastic=ward;alpha_x=0.3; alpha_y=0.1", "red plastic=ward, alpha_x=0.3 ,alpha_y=0.1;"}) {
    const CompareSpec spec = parseCompareSpec(text, twoMaterials(), "x");
    EXPECT_EQ(spec.material, 1u) << text;
    EXPECT_EQ(getParam(spec.record, "alpha_x").x, alphas.x) << text;
    EXPECT_EQ(getParam(spec.record, "alpha_y").x, alphas.y) << text;
  }
  Scene scene = twoMaterials();
  scene.materials.push_back({"a=b", lambertMaterial(glm::vec3(0.5f))});  // a name holding '='
  EXPECT_EQ(parseCompareSpec("a=b=phong", scene, "x").material, 2u);
}

// A model switch carries over what means the same thing: the colours (a red Cook-Torrance ball stays red as
// Ashikhmin-Shirley, whose Rs is a Fresnel F0 and takes its default), the roughness through the stated
// equivalences (round trips return), eta between Cook-Torrance and glass; the rest takes the model's defaults.
TEST(CompareSpecTest, ModelSwitchesCarryOverWhatMeansTheSameThing) {
  gpu::MaterialRecord record = defaultRecord(modelId("cooktorrance"));
  setParam(record, "rho_d", glm::vec3(0.6f, 0.1f, 0.1f), "t");
  setParam(record, "rho_s", glm::vec3(1.0f), "t");
  setParam(record, "m", glm::vec3(0.3f), "t");
  setParam(record, "eta", glm::vec3(1.8f), "t");
  record.delta = 0.25f;
  gpu::MaterialRecord as = record;
  switchModel(as, modelId("ashikhmin_shirley"));
  EXPECT_EQ(getParam(as, "Rd"), glm::vec3(0.6f, 0.1f, 0.1f));
  EXPECT_EQ(getParam(as, "Rs"), getParam(defaultRecord(modelId("ashikhmin_shirley")), "Rs"));
  EXPECT_NEAR(getParam(as, "nu").x, 2.0f / (0.3f * 0.3f) - 2.0f, 1e-3f);
  EXPECT_EQ(as.delta, 0.25f);
  gpu::MaterialRecord ward = record;
  switchModel(ward, modelId("ward"));
  EXPECT_EQ(getParam(ward, "rho_s"), glm::vec3(1.0f));
  EXPECT_EQ(getParam(ward, "alpha_x"), glm::vec3(0.3f));
  switchModel(ward, modelId("cooktorrance"));
  EXPECT_NEAR(getParam(ward, "m").x, 0.3f, 1e-6f);
  EXPECT_EQ(getParam(ward, "eta"), getParam(defaultRecord(modelId("cooktorrance")), "eta")) << "Ward has no eta";
  gpu::MaterialRecord phong = defaultRecord(modelId("phong"));
  setParam(phong, "s", glm::vec3(50.0f), "t");
  gpu::MaterialRecord there = phong;
  for (const std::uint32_t model : {modelId("blinnphong"), modelId("ward_gmd"), modelId("ashikhmin_shirley"),
                                    modelId("cooktorrance"), modelId("phong")}) {
    switchModel(there, model);
  }
  EXPECT_NEAR(getParam(there, "s").x, 50.0f, 0.01f) << "Phong -> ... -> Phong keeps the exponent";
  gpu::MaterialRecord glass = record;
  switchModel(glass, modelId("glass"));
  EXPECT_EQ(getParam(glass, "eta"), glm::vec3(1.8f));
  // Smooth glass to rough and back keeps the index and the tint (the transmittance role).
  setParam(glass, "tint", glm::vec3(0.2f, 0.6f, 1.0f), "t");
  gpu::MaterialRecord rough = glass;
  switchModel(rough, modelId("ggx_dielectric"));
  EXPECT_EQ(getParam(rough, "eta"), glm::vec3(1.8f));
  EXPECT_EQ(getParam(rough, "tint"), glm::vec3(0.2f, 0.6f, 1.0f));
  switchModel(rough, modelId("glass"));
  EXPECT_EQ(getParam(rough, "tint"), glm::vec3(0.2f, 0.6f, 1.0f));
  gpu::MaterialRecord invisible = defaultRecord(modelId("glass"));
  setParam(invisible, "eta", glm::vec3(1.0f), "t");
  switchModel(invisible, modelId("ggx_dielectric"));
  EXPECT_EQ(getParam(invisible, "eta").x, 1.001f) << "clamped into rough glass's range";
  // An emitter stays one: openpbr takes the emission as its own parameters, and gives it back.
  gpu::MaterialRecord lamp = defaultRecord(modelId("lambert"));
  lamp.emission = glm::vec3(2.0f, 1.0f, 0.5f);
  switchModel(lamp, modelId("openpbr"));
  EXPECT_FLOAT_EQ(getParam(lamp, "emission_luminance").x, 2.0f);
  EXPECT_EQ(getParam(lamp, "emission_color"), glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(lamp.emission, glm::vec3(2.0f, 1.0f, 0.5f));
  switchModel(lamp, modelId("lambert"));
  EXPECT_EQ(lamp.emission, glm::vec3(2.0f, 1.0f, 0.5f));
  // Every switch leaves a record whose every parameter is in range, whatever came before.
  for (const ModelInfo& from : allModels()) {
    for (const ModelInfo& to : allModels()) {
      gpu::MaterialRecord r = defaultRecord(from.id);
      // A file parameter holds a loaded file's id, not a value of a range.
      for (const ParamInfo& p : from.params) {
        if (!isFileParam(p)) setParam(r, p.name, glm::vec3(p.max), "t");
      }
      switchModel(r, to.id);
      for (const ParamInfo& p : to.params) {
        if (isFileParam(p)) continue;
        const glm::vec3 v = getParam(r, p.name);
        EXPECT_TRUE(v.x >= p.min && v.x <= p.max) << from.name << " -> " << to.name << ": " << p.name;
      }
    }
  }
}

TEST(CompareScriptTest, ComparisonEventsParseAndTheirMistakesNameTheLine) {
  const std::vector<ScriptEvent> events = parseScript(
      "at 1 compare \"red plastic=ward:alpha_x=0.3\"\n"
      "at 2 set divider 0.25\n"
      "at 2 set difference relative 0.5\n"
      "at 3 pick 10 20\n"
      "at 3 save lobe out/lobe.csv\n"
      "at 4 compare off\n",
      "s");
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[0].action, ScriptAction::kCompare);
  EXPECT_EQ(events[0].name, "red plastic=ward:alpha_x=0.3");
  EXPECT_EQ(events[1].value.x, 0.25f);
  EXPECT_EQ(events[2].param, "relative");
  EXPECT_EQ(events[2].value.x, 0.5f);
  EXPECT_EQ(glm::vec2(events[3].value), glm::vec2(10.0f, 20.0f));
  EXPECT_EQ(events[4].name, "out/lobe.csv");
  // Only the comparison itself is a new image; the divider, the difference view, picks and files are not.
  EXPECT_TRUE(resetsAccumulation(events[0]));
  for (int i = 1; i < 5; ++i) EXPECT_FALSE(resetsAccumulation(events[i])) << i;
  EXPECT_NO_THROW(checkScript(events, twoMaterials()));

  const auto fails = [](const std::string& text, const std::string& expected) {
    try {
      checkScript(parseScript(text, "t"), twoMaterials());
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  };
  fails("at 1 compare nosuch=ward\n", "t:1: the scene has no material 'nosuch'");
  fails("at 1 set divider 1.5\n", "t:1: the divider must be within [0, 1]");
  fails("at 1 set difference loud\n", "t:1");
  fails("at 1 set difference absolute 0\n", "scale must be > 0");
  fails("at 1 pick -1 3\n", "t:1");
  fails("at 1 save lobe lobe.txt\n", ".csv");
}

PointerInput over(glm::vec2 cursor, bool left, std::optional<float> divider = 0.5f) {
  PointerInput input;
  input.cursor = cursor;
  input.left = left;
  input.imageOrigin = glm::vec2(320.0f, 0.0f);  // right of the panel
  input.imageSize = glm::vec2(400.0f, 200.0f);
  input.divider = divider;
  return input;
}

TEST(PointerTest, DraggingTheDividerMovesItAndKeepsTheCameraStill) {
  PointerState state;
  PointerEvents events = updatePointer(state, over({522.0f, 100.0f}, true));  // 2 px right of the divider at 520
  EXPECT_TRUE(events.cameraBlocked);
  events = updatePointer(state, over({620.0f, 150.0f}, true));
  EXPECT_TRUE(events.cameraBlocked);
  ASSERT_TRUE(events.divider);
  EXPECT_FLOAT_EQ(*events.divider, 0.75f);
  events = updatePointer(state, over({900.0f, 150.0f}, true));  // beyond the image: clamped
  EXPECT_FLOAT_EQ(*events.divider, 1.0f);
  events = updatePointer(state, over({900.0f, 150.0f}, false));
  EXPECT_FALSE(events.cameraBlocked);
  EXPECT_FALSE(events.click) << "the end of a drag is not a click";
}

TEST(PointerTest, APressAndReleaseInPlaceIsAClickAndADragIsNot) {
  PointerState state;
  updatePointer(state, over({420.0f, 50.0f}, true));
  PointerEvents events = updatePointer(state, over({421.0f, 51.0f}, false));
  ASSERT_TRUE(events.click);
  EXPECT_NEAR(events.click->x, 101.0f / 400.0f, 1e-6f);
  EXPECT_NEAR(events.click->y, 51.0f / 200.0f, 1e-6f);

  updatePointer(state, over({420.0f, 50.0f}, true));
  updatePointer(state, over({460.0f, 50.0f}, true));  // an orbit
  events = updatePointer(state, over({420.0f, 50.0f}, false));
  EXPECT_FALSE(events.click) << "an orbit that came back is still not a click";
  EXPECT_FALSE(events.cameraBlocked);

  // Over the panel, or with ImGui holding the mouse: no click, no hover.
  PointerInput panel = over({100.0f, 50.0f}, true);
  updatePointer(state, panel);
  panel.left = false;
  events = updatePointer(state, panel);
  EXPECT_FALSE(events.click);
  EXPECT_FALSE(events.hover);
  // Without a split view there is no divider to grab: a press on its old place is a click.
  updatePointer(state, over({520.0f, 100.0f}, true, std::nullopt));
  events = updatePointer(state, over({520.0f, 100.0f}, false, std::nullopt));
  EXPECT_TRUE(events.click);
}

TEST(PointerTest, HoveringReportsWhereTheCursorRestsOverTheImage) {
  PointerState state;
  PointerEvents events = updatePointer(state, over({720.0f - 1.0f, 199.0f}, false));
  ASSERT_TRUE(events.hover);
  EXPECT_EQ(pixelAt(*events.hover, glm::uvec2(400, 200)), glm::uvec2(399, 199));
  EXPECT_FALSE(updatePointer(state, over({720.0f, 100.0f}, false)).hover) << "just right of the image";
  EXPECT_EQ(pixelAt(glm::vec2(1.0f), glm::uvec2(16, 8)), glm::uvec2(15, 7)) << "the far edge is the last pixel";
}

TEST(LobeTest, DirectionsLieInThePlaneOfIncidenceAndTheMirrorDirectionIsPlusThetaI) {
  const gpu::MaterialRecord phong = defaultRecord(modelId("phong"));
  const std::vector<gpu::BrdfEvalCase> cases = lobeCases(phong, 30.0f);
  ASSERT_EQ(cases.size(), kLobeSamples);
  EXPECT_FLOAT_EQ(lobeAngleDegrees(0), -90.0f);
  EXPECT_FLOAT_EQ(lobeAngleDegrees(kLobeSamples - 1), 90.0f);
  for (const gpu::BrdfEvalCase& c : cases) {
    EXPECT_EQ(c.wi.y, 0.0f);
    EXPECT_EQ(c.wo.y, 0.0f);
    EXPECT_GE(c.wo.z, 0.0f);
    EXPECT_NEAR(glm::length(c.wo), 1.0f, 1e-6f);
  }
  const gpu::BrdfEvalCase& mirror = cases[120];  // theta_o = +30
  EXPECT_NEAR(mirror.wo.x, -cases[0].wi.x, 1e-6f);
  EXPECT_NEAR(mirror.wo.z, cases[0].wi.z, 1e-6f);
}

TEST(LobeTest, RoughGlassIsPlottedOverTheWholePlane) {
  // A two-sided model: every degree around the plane, inside the surface below the horizon, |cos| as the weight.
  const gpu::MaterialRecord glass = defaultRecord(modelId("ggx_dielectric"));
  const std::vector<gpu::BrdfEvalCase> cases = lobeCases(glass, 30.0f);
  ASSERT_EQ(cases.size(), kLobeSamplesTwoSided);
  EXPECT_FLOAT_EQ(lobeAngleDegrees(0, true), -180.0f);
  EXPECT_FLOAT_EQ(lobeAngleDegrees(kLobeSamplesTwoSided - 1, true), 179.0f);
  int inside = 0;
  for (std::uint32_t i = 0; i < cases.size(); ++i) {
    EXPECT_NEAR(glm::length(cases[i].wo), 1.0f, 1e-6f);
    const float degrees = lobeAngleDegrees(i, true);
    if (std::abs(degrees) > 90.5f) {
      EXPECT_LT(cases[i].wo.z, 0.0f) << degrees;
      ++inside;
    }
  }
  EXPECT_GT(inside, 170);
  // The straight-through direction of light from 30 degrees (refracted towards the normal) is inside: f |cos| > 0.
  std::vector<gpu::BrdfEvalValue> values(cases.size());
  for (gpu::BrdfEvalValue& v : values) v.f = glm::vec3(2.0f);
  const std::vector<glm::vec3> fcos = lobeValues(cases, values);
  EXPECT_NEAR(fcos[0].r, 2.0f, 1e-6f) << "theta_o = -180: straight down, |cos| = 1";
  EXPECT_EQ(lobeCases(defaultRecord(modelId("ggx_conductor")), 30.0f).size(), kLobeSamples) << "one-sided: a half";
}

TEST(LobeTest, AlbedoCurveOfLambertIsItsReflectanceAtEveryAngle) {
  const AlbedoCurve curve = albedoCurve(lambertMaterial(glm::vec3(0.5f, 0.25f, 0.125f)));
  ASSERT_EQ(curve.thetaDegrees.size(), kAlbedoSamples);
  EXPECT_EQ(curve.thetaDegrees.back(), 90.0f);
  for (const glm::vec3& albedo : curve.albedo) {
    EXPECT_NEAR(albedo.r, 0.5f, 1e-4f);
    EXPECT_NEAR(albedo.g, 0.25f, 1e-4f);
    EXPECT_NEAR(albedo.b, 0.125f, 1e-4f);
  }
  gpu::MaterialRecord glass = defaultRecord(modelId("glass"));
  EXPECT_TRUE(albedoCurve(glass).albedo.empty()) << "glass has no lobe and no albedo curve";
}

}  // namespace
}  // namespace raylab::test
