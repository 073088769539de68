#include "sweep/sweep_scene.h"

#include <cmath>
#include <cstdio>

#include "brdf_params/material_params.h"
#include "shared/brdf_lobes.h"
#include "util/error.h"

namespace raylab {

namespace {

// Spheres of radius 1, one cell width apart: a cell frames its sphere with a 10% margin on every side.
constexpr float kRadius = 1.0f;
constexpr float kSpacing = 2.5f;
// A telephoto camera and a distant light: the row's own camera sees the outer spheres of an eight-sphere row
// within 9 degrees of the middle one's view, and the row's light reaches them within 5 degrees of its
// direction there, so the glTF scenes (one camera, one light) look like the contact sheets (each cell seen and
// lit exactly alike).
constexpr float kCameraDistance = 60.0f;
constexpr float kCameraElevationDegrees = 12.0f;  // enough to see a floor behind the spheres
// The overview camera frames the row, with a quarter of a cell to spare on each side, at this aspect (raylab
// render's 640x360).
constexpr float kOverviewAspect = 16.0f / 9.0f;
constexpr float kLightDistance = 100.0f;
// The key light: 40 degrees to the left of the camera and 40 degrees up, so the highlight sits on the upper
// left of the body and the terminator is in view on the lower right. Irradiance at the spheres: a white
// Lambert surface facing it has radiance 0.9.
constexpr float kLightAzimuthDegrees = 40.0f;
constexpr float kLightElevationDegrees = 40.0f;
constexpr float kIrradiance = 0.9f * 3.14159265f;
// Glass catches nothing from a point light (a smooth dielectric has no lobe), so behind glass the light only
// lights the wall. The renderer's glass blocks shadow rays like any surface (there are no caustics in a
// direct integrator), so the light comes from steeply above, which throws the spheres' shadows far below
// the frame, where only the rims of the strongest lenses see them, small. The wall's light tiles then have
// radiance 0.37.
constexpr float kWallLightElevationDegrees = 75.0f;
constexpr float kWallIrradiance = 0.55f * kIrradiance;  // on the wall, which faces the camera
// Neutral and dark, so that highlights and the diffuse body both read, and darker than a lit checker so
// that glass and mirrors show the checker as the brighter part of their surroundings.
constexpr glm::vec3 kBackground{0.05f};
// Checker tiles. The floor's period (two tiles) is the spacing, so every sphere of the row, and a cell's
// sphere in the middle, stands on a tile corner with the same colours around it.
constexpr float kFloorTile = 1.25f;
// The wall stands this far behind the spheres' centres. A glass sphere is a lens whose image of the wall is
// symmetric about the line from the camera through its centre; where that line meets the wall, the wall has
// a tile corner, for every sphere of the row and for a cell's sphere. Turned by 90 degrees about a corner the
// checker swaps its colours, so every sphere shows as much of the light tiles as of the dark ones however
// much it magnifies: the glass's brightness changes with eta, not with where a tile edge happens to fall.
constexpr float kWallDistance = 3.0f;
constexpr glm::vec3 kCheckerLight{0.75f};
constexpr glm::vec3 kCheckerDark{0.08f};

glm::vec3 towardsCamera() {
  const float e = glm::radians(kCameraElevationDegrees);
  return {0.0f, std::sin(e), std::cos(e)};
}

glm::vec3 towardsLight(float elevationDegrees) {
  const float a = glm::radians(kLightAzimuthDegrees), e = glm::radians(elevationDegrees);
  return {-std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e)};
}

// The light's intensity (W/sr) and position relative to the middle of the row.
Light keyLight(SweepStage stage) {
  if (stage == SweepStage::kCheckerWall) {
    const glm::vec3 direction = towardsLight(kWallLightElevationDegrees);
    const float irradiance = kWallIrradiance / direction.z;  // the wall's normal is +z
    return {"key", pointLight(kLightDistance * direction, glm::vec3(irradiance * kLightDistance * kLightDistance))};
  }
  return {"key", pointLight(kLightDistance * towardsLight(kLightElevationDegrees),
                            glm::vec3(kIrradiance * kLightDistance * kLightDistance))};
}

// The tiles of one parity of a checkerboard over origin + [0, columns] u + [0, rows] v, facing u x v.
// Flat-shaded: without normals the kernel uses each triangle's own.
Mesh checkerTiles(const std::string& name, glm::vec3 origin, glm::vec3 u, glm::vec3 v, int columns, int rows,
                  int parity) {
  Mesh mesh;
  mesh.name = name;
  for (int k = 0; k <= rows; ++k) {
    for (int i = 0; i <= columns; ++i) mesh.positions.push_back(origin + float(i) * u + float(k) * v);
  }
  for (int k = 0; k < rows; ++k) {
    for (int i = 0; i < columns; ++i) {
      if ((i + k) % 2 != parity) continue;
      const auto a = static_cast<std::uint32_t>(k * (columns + 1) + i);  // origin corner of the tile
      const auto b = a + static_cast<std::uint32_t>(columns + 1);        // one step along v
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
    }
  }
  return mesh;
}

// A two-colour checkerboard as two meshes, each with its own Lambert material.
void addChecker(Scene& scene, const std::string& name, glm::vec3 origin, glm::vec3 u, glm::vec3 v, int columns,
                int rows) {
  const glm::vec3 colours[2] = {kCheckerLight, kCheckerDark};
  for (int parity = 0; parity < 2; ++parity) {
    const std::string part = name + (parity == 0 ? " light" : " dark");
    scene.materials.push_back({part, lambertMaterial(colours[parity])});
    scene.meshes.push_back(checkerTiles(part, origin, u, v, columns, rows, parity));
    scene.instances.push_back({static_cast<std::uint32_t>(scene.meshes.size() - 1), glm::mat4(1.0f),
                               static_cast<std::uint32_t>(scene.materials.size() - 1)});
  }
}

float rowHalfWidth(std::uint32_t count) { return 0.5f * float(count - 1) * kSpacing + kRadius; }

void addStage(Scene& scene, SweepStage stage, std::uint32_t count) {
  const float half = rowHalfWidth(count);
  if (stage == SweepStage::kCheckerFloor) {
    // Under the row, from 20 units in front of it (the overview camera's lowest ray meets the floor 17 units
    // in front) to 20 behind, far enough that mirrors show the floor up to near their horizon.
    const int columns = 2 * static_cast<int>(std::ceil((half + 12.0f) / kFloorTile));
    const int rows = static_cast<int>(std::ceil(40.0f / kFloorTile));
    // Corners at every multiple of the tile; a row of an even count has its spheres an odd number of tiles
    // from the middle, so its pattern is shifted by one tile to give them the colours the middle has.
    const float shift = count % 2 == 0 ? kFloorTile : 0.0f;
    const glm::vec3 origin(-0.5f * float(columns) * kFloorTile + shift, -kRadius, 20.0f - float(rows) * kFloorTile);
    // u = +z, v = +x: u x v = +y, the floor faces up.
    addChecker(scene, "floor", origin, {0.0f, 0.0f, kFloorTile}, {kFloorTile, 0.0f, 0.0f}, rows, columns);
  } else if (stage == SweepStage::kCheckerWall) {
    // The row camera's line through a sphere at x meets the wall at x (cameraZ + d) / cameraZ, and at the
    // height the line through the origin meets it: a quarter of the spacing, scaled by that factor, puts
    // corners there (kWallDistance).
    const float cameraZ = kCameraDistance * towardsCamera().z;
    const float tile = 0.25f * kSpacing * (cameraZ + kWallDistance) / cameraZ;
    const float axisY = -kWallDistance * towardsCamera().y / towardsCamera().z;
    // Even counts put a corner at x = 0 and at axisY; wide and tall enough that the rays glass bends
    // furthest still land on the wall.
    const int columns = 2 * static_cast<int>(std::ceil((half + 8.0f) / tile));
    const int rows = 2 * static_cast<int>(std::ceil(8.0f / tile));
    const glm::vec3 origin(-0.5f * float(columns) * tile, axisY - 0.5f * float(rows) * tile, -kWallDistance);
    // u = +x, v = +y: u x v = +z, the wall faces the spheres.
    addChecker(scene, "wall", origin, {tile, 0.0f, 0.0f}, {0.0f, tile, 0.0f}, columns, rows);
  }
}

std::string formatSweepParam(glm::vec3 value, bool rgb) {
  if (!rgb || (value.x == value.y && value.y == value.z)) return formatSweepValue(value.x);
  return formatSweepValue(value.x) + "/" + formatSweepValue(value.y) + "/" + formatSweepValue(value.z);
}

}  // namespace

std::vector<float> sweepValues(float from, float to, std::uint32_t steps, bool logScale) {
  std::vector<float> values(steps);
  for (std::uint32_t i = 0; i < steps; ++i) {
    const double t = double(i) / double(steps - 1);
    values[i] = logScale ? float(double(from) * std::pow(double(to) / double(from), t))
                         : float(double(from) + (double(to) - double(from)) * t);
  }
  values.back() = to;  // pow and the lerp may miss it by an ulp, and range checks are exact
  return values;
}

gpu::MaterialRecord sweepBaseMaterial(std::uint32_t model) {
  gpu::MaterialRecord record = defaultRecord(model);
  // The model's own starting point (the `sweep:` line of its GLSL table), e.g. a small diffuse term so that a
  // sweep of the specular lobe shows the lobe.
  const ModelInfo& info = modelInfo(model);
  applyParamList(record, info.sweepBase, "the sweep base of " + std::string(info.name));
  return record;
}

SweepScene makeSweepScene(const SweepSpec& spec) {
  const ModelInfo* model = findModel(spec.model);
  if (model == nullptr) throw Error("sweep: unknown model '" + spec.model + "'");
  if (findParam(*model, spec.param) == nullptr) {
    throw Error("sweep: '" + spec.param + "' is not a parameter of " + spec.model);
  }
  if (spec.steps < 2) throw Error("sweep: a sweep needs at least 2 steps");
  const std::string where = "sweep " + spec.model;

  SweepScene sweep;
  sweep.spec = spec;
  sweep.values = sweepValues(spec.from, spec.to, spec.steps, spec.logScale);
  sweep.fixed = sweepBaseMaterial(model->id);
  for (const auto& [name, value] : spec.fixed) setParam(sweep.fixed, name, value, where);

  bool mirrors = sweep.fixed.delta > 0.0f;
  Scene& scene = sweep.scene;
  scene.name = "sweep_" + spec.model + "_" + spec.param;
  scene.background = kBackground;
  for (std::uint32_t i = 0; i < spec.steps; ++i) {
    gpu::MaterialRecord record = sweep.fixed;
    setParam(record, spec.param, glm::vec3(sweep.values[i]), where);
    mirrors = mirrors || record.delta > 0.0f;
    scene.materials.push_back({spec.model + " " + sweepLabel(sweep, i), record});
    const float x = (float(i) - 0.5f * float(spec.steps - 1)) * kSpacing;
    scene.spheres.push_back({{x, 0.0f, 0.0f}, kRadius, static_cast<std::uint32_t>(scene.materials.size() - 1)});
  }
  sweep.stage = (model->lobes & gpu::kLobeTransmission) != 0 ? SweepStage::kCheckerWall
                : mirrors                     ? SweepStage::kCheckerFloor
                                              : SweepStage::kPlain;
  addStage(scene, sweep.stage, spec.steps);

  sweep.rowCamera.name = "row";
  sweep.rowCamera.target = glm::vec3(0.0f);
  sweep.rowCamera.position = kCameraDistance * towardsCamera();
  sweep.rowCamera.up = {0.0f, 1.0f, 0.0f};
  sweep.rowCamera.yfov = 2.0f * std::atan(0.5f * kSpacing / kCameraDistance);
  scene.camera = sweep.rowCamera;
  scene.camera.name = "camera";
  const float overviewWidth = (float(spec.steps) + 0.5f) * kSpacing;
  scene.camera.yfov = 2.0f * std::atan(0.5f * overviewWidth / kOverviewAspect / kCameraDistance);
  scene.lights.push_back(keyLight(sweep.stage));
  return sweep;
}

Scene cellScene(const SweepScene& sweep) {
  Scene scene = sweep.scene;
  scene.camera = sweep.rowCamera;
  scene.spheres = {{glm::vec3(0.0f), kRadius, sweep.scene.spheres.front().material}};
  return scene;
}

std::vector<Material> cellMaterials(const SweepScene& sweep, std::uint32_t cell) {
  std::vector<Material> materials = sweep.scene.materials;
  materials.at(sweep.scene.spheres.front().material) = materials.at(sweep.scene.spheres.at(cell).material);
  return materials;
}

std::string formatSweepValue(float value) {
  char text[32];
  if (std::fabs(value) >= 1000.0f && std::fabs(value) < 1e5f) std::snprintf(text, sizeof text, "%.0f", value);
  else std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string sweepLabel(const SweepScene& sweep, std::uint32_t cell) {
  return sweep.spec.param + " = " + formatSweepValue(sweep.values.at(cell));
}

std::string sweepTitle(const SweepScene& sweep) {
  const ModelInfo& model = modelInfo(sweep.fixed.model);
  std::string title = sweep.spec.model + ": " + sweep.spec.param + " from " + formatSweepValue(sweep.spec.from) +
                      " to " + formatSweepValue(sweep.spec.to) + (sweep.spec.logScale ? " (log)" : "");
  for (const ParamInfo& param : model.params) {
    if (param.name == sweep.spec.param) continue;
    title += ", " + std::string(param.name) + " = " + formatSweepParam(getParam(sweep.fixed, param.name), param.rgb);
  }
  if (sweep.spec.param != deltaParam().name && sweep.fixed.delta != 0.0f) {
    title += ", delta = " + formatSweepValue(sweep.fixed.delta);
  }
  return title;
}

}  // namespace raylab
