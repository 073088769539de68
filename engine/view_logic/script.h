// Viewer scripts: a small line-based list of camera and parameter changes, each at a frame number, that
// `raylab view --script FILE` replays (tests, benchmarks, documentation shots). Format (docs/viewer.md):
//
//   # comment
//   at <frame> orbit <yaw-degrees> <pitch-degrees>
//   at <frame> pan <dx> <dy>                       fractions of the view height
//   at <frame> zoom <factor>                       distance to the target times factor
//   at <frame> set material <name> <param> <value> [<g> <b>]
//   at <frame> set light <name> intensity <r> <g> <b>
//   at <frame> set light <name> position <x> <y> <z>
//   at <frame> set light <name> direction <x> <y> <z>   spot and directional lights
//   at <frame> set light <name> cone <inner> <outer>    spot lights, degrees from the axis
//   at <frame> set exposure <stops>
//   at <frame> set max-depth <bounces>
//   at <frame> denoise on|off                      the denoised view of the still image (as the N key)
//   at <frame> set integrator slides|path
//   at <frame> set environment strength <S>        the environment image's; S >= 0
//   at <frame> set environment rotation <degrees>  about +Y
//   at <frame> model <material> <model>
//   at <frame> resize <width> <height>
//   at <frame> screenshot <file.exr|file.png>      also writes the other beside it; frame >= 1
//   at <frame> compare <material>=<model>[:k=v,...]  the split view (as view --compare); `compare off` ends it
//   at <frame> set divider <fraction>              the split view's divider, 0 (left edge) to 1
//   at <frame> set difference off|absolute|relative [<scale>]   the difference view and its colour scale
//   at <frame> pick <x> <y>                        as a click on image pixel (x, y): selects its material
//   at <frame> save lobe <file.csv>                the selected material's lobe plot and albedo curve
//
// Names containing spaces are written in double quotes. Events of one frame apply in file order, before that
// frame is traced.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace raylab {

enum class ScriptAction {
  kOrbit,
  kPan,
  kZoom,
  kSetMaterial,
  kSetLightIntensity,
  kSetLightPosition,
  kSetLightDirection,
  kSetLightCone,
  kSetExposure,
  kSetMaxDepth,
  kSetIntegrator,            // param: a value of the integrator option (util/render_options.h)
  kSetEnvironmentStrength,
  kSetEnvironmentRotation,   // value.x in degrees
  kModel,
  kResize,
  kScreenshot,
  kCompare,        // name: the MATERIAL=MODEL[:k=v,...] spec, or "off"
  kSetDivider,     // value.x in [0, 1]
  kSetDifference,  // param: "off", "absolute" or "relative"; value.x the scale when valueCount is 1
  kPick,           // value.xy: the image pixel
  kSaveLobe,       // name: the CSV file
  kDenoise,        // param: "on" or "off"
};

struct ScriptEvent {
  std::uint32_t frame = 0;
  ScriptAction action = ScriptAction::kOrbit;
  std::string where;      // "file:line", for error messages
  std::string name;       // material or light; the model for kModel is `param`; the file for kScreenshot
  std::string param;      // material parameter, or model name
  glm::vec3 value{0.0f};  // numbers of the event; a single number for a scalar parameter is in x
  int valueCount = 0;
  std::string path;       // kSetMaterial of a file parameter (measured's file): the file, relative to the script's folder
  std::string word;       // kSetMaterial of one word that is not a number, as written: a preset's name (metal Au)
};

// Parses `text` (read from `path`, which errors name with the line). Events come out sorted by frame, file
// order kept within a frame.
std::vector<ScriptEvent> parseScript(const std::string& text, const std::string& path);
std::vector<ScriptEvent> loadScript(const std::string& path);

struct SceneEffect {
  bool materials = false;  // upload the materials (and check the kernel has their models)
  bool lights = false;     // upload the lights
};

// Applies a material, model or light event to `scene` (other events touch nothing here), and checks a compare
// event's spec against it. Throws Error naming the line when a name or value is wrong.
SceneEffect applyToScene(const ScriptEvent& event, Scene& scene);

// Applies the whole script to a copy of `scene`, so that a typo fails before the window opens.
void checkScript(const std::vector<ScriptEvent>& events, const Scene& scene);

// True for events after which the accumulated samples are stale (not screenshots, exposure, the divider, the
// difference view, picks or lobe files, which only the display pass or the panel use).
bool resetsAccumulation(const ScriptEvent& event);

}  // namespace raylab
