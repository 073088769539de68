// The scene of one parameter sweep, laid out like the figures of the original slides: a row of spheres, one
// per value of the swept parameter, lit from the upper front left by one point light, in front of a neutral
// background (a checker floor when the spheres mirror, a checker wall behind glass). `raylab sweep` renders
// it cell by cell into a contact sheet; `raylab sweep --gltf` writes it as the glTF scenes of assets/scenes.
// docs/gallery.md describes the layout and why.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

struct SweepSpec {
  std::string model;  // a model of material_params.h
  std::string param;  // one of its parameters, or delta
  float from = 0.0f;
  float to = 1.0f;
  std::uint32_t steps = 8;  // at least 2
  bool logScale = false;    // geometric steps (both bounds > 0)
  // Other parameters (name, value; RGB or a splat), applied after the layout's own defaults.
  std::vector<std::pair<std::string, glm::vec3>> fixed;
};

// What surrounds the spheres: chosen from the materials, so that reflections and refractions have something
// to show.
enum class SweepStage {
  kPlain,         // the background only
  kCheckerFloor,  // the spheres rest on a checkerboard (mirror weight delta > 0)
  kCheckerWall,   // the spheres float in front of a checkered wall (glass)
};

struct SweepScene {
  SweepSpec spec;
  std::vector<float> values;       // one per sphere, left to right
  gpu::MaterialRecord fixed{};     // the material before the swept parameter is set (the title's values)
  SweepStage stage = SweepStage::kPlain;
  // The whole row: spheres along +x centred on the origin, the light placed for the middle of the row, and
  // a camera ("camera") that frames the whole row in a 16:9 image, raylab render's default shape. Spheres are
  // sorted left to right: scene.spheres[i] has values[i].
  Scene scene;
  // The same camera with the field of view of one cell ("row"): the row fills an N:1 image, one square cell
  // per sphere, and a cell's camera is this one.
  Camera rowCamera;
};

// The values of a sweep: linear or geometric from `from` to `to`, both included. `to` is exact.
std::vector<float> sweepValues(float from, float to, std::uint32_t steps, bool logScale);

// The layout's defaults for `model` on top of material_params' (a little diffuse under a strong specular lobe,
// as the slides showed). Parameters the layout does not change keep material_params' defaults.
gpu::MaterialRecord sweepBaseMaterial(std::uint32_t model);

// Builds the row. The spec must be valid (known model and parameter, values inside the parameter's range):
// anything else throws Error naming the parameter, the value and the range.
SweepScene makeSweepScene(const SweepSpec& spec);

// The scene of one cell of a contact sheet: one sphere alone in the middle of the row (no neighbour to shadow
// it or to show in its reflections), under the row's camera and light and on its stage, so that every cell
// sees and lights its sphere exactly alike. The camera frames it square, the sphere filling 80% of the frame.
// Its materials are the row's: cellMaterials(sweep, i) puts cell i's material on the sphere, so one upload
// and one kernel serve every cell.
Scene cellScene(const SweepScene& sweep);
std::vector<Material> cellMaterials(const SweepScene& sweep, std::uint32_t cell);

// "phong: s from 1 to 1000 (log), rho_d = 0.1, rho_s = 0.9"
std::string sweepTitle(const SweepScene& sweep);
// "s = 31.6"
std::string sweepLabel(const SweepScene& sweep, std::uint32_t cell);
// Numbers for humans: 3 significant digits, no exponent below 10^5 ("0.00139", "31.6", "1000").
std::string formatSweepValue(float value);

}  // namespace raylab
