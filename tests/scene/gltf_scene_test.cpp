// The node hierarchy of a glTF scene: transforms, cameras, KHR_lights_punctual lights, raylab spheres, the
// scene's background and the defaults for files without a camera or lights.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_test_support.h"

namespace raylab::test {
namespace {

using nlohmann::json;

constexpr float kTolerance = 1e-5f;

void expectNear(glm::vec3 actual, glm::vec3 expected, const std::string& what, float tolerance = kTolerance) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " component " << i;
}

// A quaternion [x, y, z, w] as glTF writes it.
json rotation(float degrees, glm::vec3 axis) {
  const glm::quat q = glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
  return {q.x, q.y, q.z, q.w};
}

TEST(GltfScene, ChildTransformsComposeWithTheirParents) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  const int child = b.addNode({{"mesh", mesh}, {"translation", {0, 0, 1}}}, false);
  b.addNode({{"translation", {1, 0, 0}}, {"rotation", rotation(90, {0, 1, 0})}, {"scale", {2, 2, 2}},
             {"children", {child}}});
  const Scene scene = b.load();
  ASSERT_EQ(scene.instances.size(), 1u);
  // The child's origin: parent translation + parent rotation (90 deg about y turns +z into +x) of 2 * (0, 0, 1).
  const glm::vec3 origin(scene.instances[0].transform * glm::vec4(0, 0, 0, 1));
  expectNear(origin, {3, 0, 0}, "child origin");
  const glm::vec3 xAxis(scene.instances[0].transform * glm::vec4(1, 0, 0, 0));
  expectNear(xAxis, {0, 0, -2}, "child x axis");
}

TEST(GltfScene, MatrixAndTrsGiveTheSameTransform) {
  const glm::mat4 trs = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                        glm::mat4_cast(glm::angleAxis(glm::radians(30.0f), glm::normalize(glm::vec3(1, 1, 0)))) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 2.0f, 1.5f));
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.addNode({{"mesh", mesh}, {"translation", {1, 2, 3}}, {"rotation", rotation(30, {1, 1, 0})},
             {"scale", {0.5, 2.0, 1.5}}});
  json matrix = json::array();
  for (int i = 0; i < 16; ++i) matrix.push_back(glm::value_ptr(trs)[i]);  // column-major, as glTF
  b.addNode({{"mesh", mesh}, {"matrix", matrix}});
  const Scene scene = b.load();
  ASSERT_EQ(scene.instances.size(), 2u);
  for (int column = 0; column < 4; ++column) {
    expectNear(glm::vec3(scene.instances[0].transform[column]), glm::vec3(trs[column]), "TRS column");
    expectNear(glm::vec3(scene.instances[1].transform[column]), glm::vec3(trs[column]), "matrix column");
  }
  // One glTF mesh used twice is one raylab mesh with two instances.
  EXPECT_EQ(scene.meshes.size(), 1u);
}

TEST(GltfScene, ACycleInTheNodeHierarchyIsAnError) {
  GltfBuilder b;
  b.addQuad();
  b.doc()["nodes"] = {{{"name", "a"}, {"children", {1}}, {"mesh", 0}}, {{"name", "b"}, {"children", {0}}}};
  b.doc()["scenes"][0]["nodes"] = {0};
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: node 0 'a': is its own ancestor"), std::string::npos) << error;
}

TEST(GltfScene, ChildIndexOutOfRangeIsAnError) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}, {"children", {7}}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("node 7 does not exist"), std::string::npos) << error;
}

json perspective(const std::string& name, double yfov) {
  return {{"name", name}, {"type", "perspective"}, {"perspective", {{"yfov", yfov}, {"znear", 0.1}}}};
}

TEST(GltfScene, CameraLooksDownItsNodesMinusZWithYUp) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {perspective("cam", 0.5)};
  // Turned 90 degrees about +y: -Z becomes -X; raised to y = 2.
  b.addNode({{"name", "camera node"}, {"camera", 0}, {"translation", {5, 2, 0}},
             {"rotation", rotation(90, {0, 1, 0})}});
  const Scene scene = b.load();
  EXPECT_EQ(scene.camera.name, "cam");
  expectNear(scene.camera.position, {5, 2, 0}, "position");
  expectNear(glm::normalize(scene.camera.target - scene.camera.position), {-1, 0, 0}, "view direction");
  expectNear(scene.camera.up, {0, 1, 0}, "up");
  EXPECT_FLOAT_EQ(scene.camera.yfov, 0.5f);
}

TEST(GltfScene, TheFirstCameraOfTheListIsChosenAndNamesSelectOthers) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {perspective("first", 0.4), perspective("second", 0.6)};
  // The second camera's node comes first in the hierarchy; the file's camera order still decides.
  b.addNode({{"name", "node of second"}, {"camera", 1}, {"translation", {0, 0, 9}}});
  b.addNode({{"name", "node of first"}, {"camera", 0}, {"translation", {0, 0, 5}}});
  EXPECT_EQ(b.load().camera.name, "first");
  EXPECT_EQ(b.load({"second"}).camera.name, "second");
  const Scene byNode = b.load({"node of second"});
  EXPECT_EQ(byNode.camera.name, "second");
  expectNear(byNode.camera.position, {0, 0, 9}, "position of the camera named by its node");
  const std::string error = errorOf([&] { b.load({"third"}); });
  EXPECT_NE(error.find("has no camera named 'third' (cameras: 'second', 'first')"), std::string::npos) << error;
}

TEST(GltfScene, OrthographicCamerasAreSkippedWithOneWarningOrRejectedWhenNamed) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {{{"name", "ortho"}, {"type", "orthographic"},
                         {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"zfar", 10}, {"znear", 0.1}}}},
                        perspective("persp", 0.7)};
  b.addNode({{"camera", 0}});
  b.addNode({{"camera", 1}, {"translation", {0, 0, 4}}});
  WarningCapture warnings;
  EXPECT_EQ(b.load().camera.name, "persp");
  EXPECT_EQ(warnings.count("orthographic cameras"), 1);
  const std::string error = errorOf([&] { b.load({"ortho"}); });
  EXPECT_NE(error.find("camera 'ortho' is orthographic; raylab renders perspective cameras only"), std::string::npos)
      << error;
}

TEST(GltfScene, AFieldOfViewOutsideTheRendererRangeIsAnError) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["cameras"] = {perspective("wide", 3.2)};
  b.addNode({{"camera", 0}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("camera 0 'wide': yfov"), std::string::npos) << error;
}

TEST(GltfScene, WithoutACameraTheBoundsAreFramedFromPlusZ) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}, {"translation", {10, 0, 0}}});
  WarningCapture warnings;
  const Scene scene = b.load();
  EXPECT_EQ(warnings.count("has no perspective camera; framing the scene's bounds"), 1);
  expectNear(scene.camera.target, {10.5f, 0.5f, 0.0f}, "target: the bounds' centre");
  const glm::vec3 back = glm::normalize(scene.camera.position - scene.camera.target);
  EXPECT_GT(back.z, 0.9f) << "the default camera looks from +z";
  EXPECT_GT(back.y, 0.0f) << "and from slightly above";
  // The bounding sphere (radius sqrt(2)/2) fits in the vertical field of view.
  const float distance = glm::length(scene.camera.position - scene.camera.target);
  EXPECT_GE(std::sin(0.5f * scene.camera.yfov) * distance, std::sqrt(0.5f));
}

TEST(GltfScene, WithoutLightsADefaultLightIsAddedWithOneWarning) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  WarningCapture warnings;
  const Scene scene = b.load();
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(warnings.count("has no KHR_lights_punctual lights; added a default headlight"), 1);
  const PunctualLight& light = scene.lights[0].record;
  // A headlight: its position is an offset along the camera's right, up and forward axes (above and left).
  EXPECT_EQ(light.type, gpu::kLightHeadlight);
  EXPECT_LT(light.position.x, 0.0f);
  EXPECT_GT(light.position.y, 0.0f);
  EXPECT_EQ(light.position.z, 0.0f);
  const Camera& camera = scene.camera;
  const glm::vec3 w = glm::normalize(camera.target - camera.position);
  const glm::vec3 u = glm::normalize(glm::cross(w, camera.up));
  const glm::vec3 v = glm::cross(u, w);
  const glm::vec3 world = camera.position + light.position.x * u + light.position.y * v;
  // Documented: white Lambert at the bounds' centre, facing the light, has radiance 0.8.
  const float distance = glm::length(world - glm::vec3(0.5f, 0.5f, 0.0f));
  EXPECT_NEAR(light.intensity.r / (distance * distance) / 3.14159265f, 0.8f, 1e-4f);
}

TEST(GltfScene, PunctualLightsTakeTheirNodesPositionAndMinusZ) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  const int point = b.addLight({{"name", "bulb"}, {"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 40},
                                {"range", 3}});
  const int spot = b.addLight({{"type", "spot"}, {"intensity", 10}, {"spot", {{"innerConeAngle", 0.2},
                                                                               {"outerConeAngle", 0.5}}}});
  const int sun = b.addLight({{"type", "directional"}, {"intensity", 2}, {"color", {1, 1, 0.9}}});
  const auto uses = [](int light) { return json{{"KHR_lights_punctual", {{"light", light}}}}; };
  b.addNode({{"translation", {1, 2, 3}}, {"extensions", uses(point)}});
  // -Z turned 90 degrees about +x points down (-y).
  const int spotNode = b.addNode({{"translation", {0, 4, 0}}, {"rotation", rotation(-90, {1, 0, 0})},
                                  {"extensions", uses(spot)}}, false);
  b.addNode({{"translation", {0, 1, 0}}, {"children", {spotNode}}});
  b.addNode({{"rotation", rotation(90, {0, 1, 0})}, {"extensions", uses(sun)}});
  b.doc()["cameras"] = {perspective("cam", 0.5)};
  b.addNode({{"camera", 0}, {"translation", {0, 0, 5}}});
  WarningCapture warnings;
  const Scene scene = b.load();
  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_TRUE(warnings.messages().empty()) << warnings.messages()[0];

  const PunctualLight& p = scene.lights[0].record;
  EXPECT_EQ(scene.lights[0].name, "bulb");
  EXPECT_EQ(p.type, gpu::kLightPoint);
  expectNear(p.position, {1, 2, 3}, "point position");
  expectNear(p.intensity, {40, 20, 10}, "point intensity times colour (W/sr); range ignored");

  const PunctualLight& s = scene.lights[1].record;
  EXPECT_EQ(s.type, gpu::kLightSpot);
  expectNear(s.position, {0, 5, 0}, "spot position under its parent");
  expectNear(s.direction, {0, -1, 0}, "spot direction");
  EXPECT_NEAR(s.cosInner, std::cos(0.2f), 1e-6f);
  EXPECT_NEAR(s.cosOuter, std::cos(0.5f), 1e-6f);

  const PunctualLight& d = scene.lights[2].record;
  EXPECT_EQ(d.type, gpu::kLightDirectional);
  expectNear(d.direction, {-1, 0, 0}, "directional direction");
  expectNear(d.intensity, {2, 2, 1.8f}, "irradiance times colour (W/m^2)");
}

TEST(GltfScene, SpotConesMustNestInsideAQuarterTurn) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  const int spot = b.addLight({{"name", "lamp"}, {"type", "spot"},
                               {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.4}}}});
  b.addNode({{"name", "holder"}, {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("light 0 'lamp' (at node 1 'holder'): spot cone angles"), std::string::npos) << error;
}

TEST(GltfScene, ALightIndexOutOfRangeIsAnError) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.addLight({{"type", "point"}});
  b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("KHR_lights_punctual light 3 does not exist"), std::string::npos) << error;
}

TEST(GltfScene, RaylabSpheresAreExactSpheresInWorldSpace) {
  GltfBuilder b;
  const int red = b.addMaterial({{"name", "red"}});
  const int blue = b.addMaterial({{"name", "blue"}});
  const int standIn = b.addQuad(blue);
  const int ball = b.addNode({{"name", "ball"}, {"translation", {0, 1, 0}}, {"scale", {2, 2, 2}}, {"mesh", standIn},
                              {"extras", {{"raylab", {{"sphere", {{"radius", 0.5}, {"material", red}}}}}}}},
                             false);
  b.addNode({{"translation", {3, 0, 0}}, {"children", {ball}}});
  // Without "material": the stand-in mesh's first primitive decides.
  b.addNode({{"mesh", standIn}, {"extras", {{"raylab", {{"sphere", {{"radius", 1}}}}}}}});
  const Scene scene = b.load();
  ASSERT_EQ(scene.spheres.size(), 2u);
  expectNear(scene.spheres[0].center, {3, 1, 0}, "centre");
  EXPECT_FLOAT_EQ(scene.spheres[0].radius, 1.0f);
  EXPECT_EQ(scene.spheres[0].material, std::uint32_t(red));
  EXPECT_EQ(scene.spheres[1].material, std::uint32_t(blue));
  EXPECT_TRUE(scene.instances.empty()) << "a sphere replaces its node's mesh";
}

TEST(GltfScene, ARaylabSphereUnderNonUniformScaleIsAnErrorNamingTheNode) {
  GltfBuilder b;
  b.addMaterial(json::object());
  const json sphere = {{"radius", 1}, {"material", 0}};
  const int ball = b.addNode({{"name", "egg"}, {"extras", {{"raylab", {{"sphere", sphere}}}}}}, false);
  b.addNode({{"name", "squash"}, {"scale", {1, 1.5, 1}}, {"children", {ball}}});
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: node 0 'egg': a raylab sphere needs a uniform scale"), std::string::npos) << error;
  EXPECT_NE(error.find("(1, 1.5, 1)"), std::string::npos) << error;
}

TEST(GltfScene, RaylabSphereKeysAreChecked) {
  const auto errorFor = [](const json& raylab) {
    GltfBuilder b;
    b.addMaterial(json::object());
    b.addNode({{"name", "s"}, {"extras", {{"raylab", raylab}}}});
    return errorOf([&] { b.load(); });
  };
  EXPECT_NE(errorFor({{"sphere", {{"radius", 1}, {"colour", 2}}}}).find("unknown key 'colour'"), std::string::npos);
  EXPECT_NE(errorFor({{"sphere", {{"radius", -1}}}}).find("radius: expected a finite number > 0"), std::string::npos);
  EXPECT_NE(errorFor({{"sphere", {{"radius", 1}, {"material", 4}}}}).find("material: 4 is not a material index"),
            std::string::npos);
  EXPECT_NE(errorFor({{"box", {}}}).find("node 0 's': extras.raylab: unknown key 'box'"), std::string::npos);
}

TEST(GltfScene, SceneExtrasSetTheBackground) {
  GltfBuilder b;
  b.addNode({{"mesh", b.addQuad()}});
  b.doc()["scenes"][0]["extras"] = {{"raylab", {{"background", {0.1, 0.2, 0.3}}}}};
  expectNear(b.load().background, {0.1f, 0.2f, 0.3f}, "background");
  b.doc()["scenes"][0]["extras"] = {{"raylab", {{"background", {0.1, -0.2, 0.3}}}}};
  EXPECT_NE(errorOf([&] { b.load(); }).find("extras.raylab.background: expected [r, g, b] of finite numbers >= 0"),
            std::string::npos);
  b.doc()["scenes"][0]["extras"] = {{"raylab", {{"fog", 1}}}};
  EXPECT_NE(errorOf([&] { b.load(); }).find("unknown key 'fog'"), std::string::npos);
}

TEST(GltfScene, AnEmptySceneIsAnError) {
  GltfBuilder b;
  const std::string error = errorOf([&] { b.load(); });
  EXPECT_NE(error.find("test: the scene has nothing to render"), std::string::npos) << error;
}

TEST(GltfScene, ZeroScaleHidesAMeshWithOneWarning) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.addNode({{"mesh", mesh}});
  b.addNode({{"name", "hidden"}, {"mesh", mesh}, {"scale", {0, 0, 0}}});
  WarningCapture warnings;
  EXPECT_EQ(b.load().instances.size(), 1u);
  EXPECT_EQ(warnings.count("node 1 'hidden': has a zero scale"), 1);
}

}  // namespace
}  // namespace raylab::test
