#include "view_logic/script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "brdf_params/material_params.h"
#include "image/image.h"
#include "scene/radiance_limits.h"
#include "shared/scene_records.h"
#include "util/error.h"
#include "util/render_options.h"
#include "util/files.h"
#include "util/number_text.h"
#include "view_logic/compare_spec.h"
#include "view_logic/scene_edits.h"

namespace raylab {

namespace {

// Splits a line into words; "double quoted" words may contain spaces. A # outside quotes starts a comment.
std::vector<std::string> splitWords(const std::string& line, const std::string& where) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '#') {
      break;
    } else if (c == '"') {
      const std::size_t end = line.find('"', i + 1);
      if (end == std::string::npos) throw Error(where + ": unterminated quoted name");
      words.push_back(line.substr(i + 1, end - i - 1));
      i = end + 1;
    } else {
      std::size_t end = i;
      while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
      words.push_back(line.substr(i, end - i));
      i = end;
    }
  }
  return words;
}

bool finiteInFloat(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float parseNumber(const std::string& word, const std::string& where, const char* what) {
  float value = 0.0f;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
    throw Error(where + ": " + what + " must be a number, not '" + word + "'");
  }
  return value;
}

std::uint32_t parseCount(const std::string& word, const std::string& where, const char* what) {
  std::uint32_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) {
    throw Error(where + ": " + what + " must be a whole number >= 0, not '" + word + "'");
  }
  return value;
}

void expectWords(const std::vector<std::string>& words, std::size_t count, const std::string& where,
                 const std::string& form) {
  if (words.size() != count) throw Error(where + ": expected '" + form + "'");
}

void readValues(ScriptEvent& event, const std::vector<std::string>& words, std::size_t first, const char* what) {
  for (std::size_t i = first; i < words.size(); ++i) {
    event.value[event.valueCount++] = parseNumber(words[i], event.where, what);
  }
}

// A path of the script, relative to its folder unless absolute.
std::string scriptRelative(const std::string& text, const std::string& scriptFolder) {
  const std::filesystem::path file(text);
  return file.is_absolute() ? text : (std::filesystem::path(scriptFolder) / file).string();
}

ScriptEvent parseLine(const std::vector<std::string>& words, const std::string& where, const std::string& scriptFolder) {
  if (words.size() < 3 || words[0] != "at") {
    throw Error(where + ": expected 'at <frame> <action> ...' (actions: orbit, pan, zoom, set, model, resize, "
                        "screenshot, compare, pick, save)");
  }
  ScriptEvent event;
  event.where = where;
  event.frame = parseCount(words[1], where, "the frame");
  const std::string& action = words[2];
  if (action == "orbit" || action == "pan") {
    expectWords(words, 5, where, action == "orbit" ? "at <frame> orbit <yaw-degrees> <pitch-degrees>"
                                                   : "at <frame> pan <dx> <dy>");
    event.action = action == "orbit" ? ScriptAction::kOrbit : ScriptAction::kPan;
    readValues(event, words, 3, "an offset");
    if (event.action == ScriptAction::kPan && !(std::abs(event.value.x) <= 1e3f && std::abs(event.value.y) <= 1e3f)) {
      throw Error(where + ": a pan moves at most 1000 view heights");
    }
  } else if (action == "zoom") {
    expectWords(words, 4, where, "at <frame> zoom <factor>");
    event.action = ScriptAction::kZoom;
    readValues(event, words, 3, "the zoom factor");
    // A camera moved by more than this in one step leaves float range or collapses onto its target.
    if (!(event.value.x >= 1e-3f && event.value.x <= 1e3f)) {
      throw Error(where + ": the zoom factor must be within [0.001, 1000], not " + words[3]);
    }
  } else if (action == "model") {
    if (words.size() != 5 && words.size() != 6) {
      throw Error(where + ": expected 'at <frame> model <material> <model> [<file> of a measured model]'");
    }
    event.action = ScriptAction::kModel;
    event.name = words[3];
    event.param = words[4];
    if (words.size() == 6) event.path = scriptRelative(words[5], scriptFolder);
  } else if (action == "resize") {
    expectWords(words, 5, where, "at <frame> resize <width> <height>");
    event.action = ScriptAction::kResize;
    const std::uint32_t width = parseCount(words[3], where, "the width");
    const std::uint32_t height = parseCount(words[4], where, "the height");
    if (width < 8 || height < 8 || width > kMaxImageSide || height > kMaxImageSide) {
      throw Error(where + ": the window size must be within 8.." + std::to_string(kMaxImageSide) + " pixels a side");
    }
    event.value = glm::vec3(float(width), float(height), 0.0f);
    event.valueCount = 2;
  } else if (action == "screenshot") {
    expectWords(words, 4, where, "at <frame> screenshot <file.exr|file.png>");
    event.action = ScriptAction::kScreenshot;
    event.name = words[3];
    const std::string extension = std::filesystem::path(event.name).extension().string();
    if (extension != ".exr" && extension != ".png") {
      throw Error(where + ": the screenshot file must end in .exr or .png");
    }
    // Events of frame N apply before frame N is traced: at frame 0 nothing has been traced yet.
    if (event.frame == 0) throw Error(where + ": a screenshot at frame 0 would be black (nothing traced yet); use 1 or later");
  } else if (action == "denoise") {
    expectWords(words, 4, where, "at <frame> denoise on|off");
    if (words[3] != "on" && words[3] != "off") throw Error(where + ": denoise is on or off, not '" + words[3] + "'");
    event.action = ScriptAction::kDenoise;
    event.param = words[3];
  } else if (action == "compare") {
    expectWords(words, 4, where, "at <frame> compare <material>=<model>[:k=v,...] | off");
    event.action = ScriptAction::kCompare;
    event.name = words[3];  // checked against the scene by applyToScene
  } else if (action == "pick") {
    expectWords(words, 5, where, "at <frame> pick <x> <y>");
    event.action = ScriptAction::kPick;
    // Pixel coordinates stay exact in the event's floats: a window is at most 2^24 pixels a side.
    const std::uint32_t x = parseCount(words[3], where, "x"), y = parseCount(words[4], where, "y");
    if (x >= (1u << 24) || y >= (1u << 24)) {
      throw Error(where + ": pick " + words[3] + " " + words[4] + " lies outside any window (pixels are below 2^24)");
    }
    event.value = glm::vec3(float(x), float(y), 0.0f);
    event.valueCount = 2;
  } else if (action == "save") {
    if (words.size() != 5 || words[3] != "lobe") throw Error(where + ": expected 'at <frame> save lobe <file.csv>'");
    event.action = ScriptAction::kSaveLobe;
    event.name = words[4];
    if (std::filesystem::path(event.name).extension() != ".csv") throw Error(where + ": the lobe file must end in .csv");
  } else if (action == "set") {
    if (words.size() < 5) {
      throw Error(where + ": expected 'at <frame> set material|light|exposure|max-depth|integrator|environment|"
                          "divider|difference ...'");
    }
    const std::string& what = words[3];
    if (what == "material") {
      if (words.size() != 7 && words.size() != 9) {
        throw Error(where + ": expected 'at <frame> set material <name> <param> <value> [<g> <b>]'");
      }
      event.action = ScriptAction::kSetMaterial;
      event.name = words[4];
      event.param = words[5];
      float number = 0.0f;
      const std::string& first = words[6];
      const bool numeric = std::from_chars(first.data(), first.data() + first.size(), number).ptr == first.data() + first.size();
      if (words.size() == 7 && !numeric) {
        // A file parameter's path (`set material ball file gold.binary`), relative to the script's folder, or a
        // preset's name (`set material ball metal Au`): which one, the material's model decides (applyToScene).
        event.path = scriptRelative(first, scriptFolder);
        event.word = first;
      } else {
        readValues(event, words, 6, "a parameter value");
      }
    } else if (what == "light") {
      if (words.size() < 6) throw Error(where + ": expected 'at <frame> set light <name> intensity|position|direction|cone ...'");
      event.name = words[4];
      const std::string& property = words[5];
      if (property == "cone") {
        expectWords(words, 8, where, "at <frame> set light <name> cone <inner-degrees> <outer-degrees>");
        event.action = ScriptAction::kSetLightCone;
        readValues(event, words, 6, "a cone angle");
        if (!(event.value.x >= 0.0f && event.value.x < event.value.y && event.value.y <= 90.0f)) {
          throw Error(where + ": cone angles must satisfy 0 <= inner < outer <= 90 degrees");
        }
      } else {
        expectWords(words, 9, where, "at <frame> set light <name> intensity|position|direction <x> <y> <z>");
        if (property == "intensity") event.action = ScriptAction::kSetLightIntensity;
        else if (property == "position") event.action = ScriptAction::kSetLightPosition;
        else if (property == "direction") event.action = ScriptAction::kSetLightDirection;
        else throw Error(where + ": a light has intensity, position, direction and cone, not '" + property + "'");
        readValues(event, words, 6, "a light value");
        if (event.action == ScriptAction::kSetLightIntensity) checkLightIntensity(event.value, where);
        if (event.action == ScriptAction::kSetLightDirection) {
          if (!(glm::length(event.value) > 0.0f) || !finiteInFloat(event.value)) {
            throw Error(where + ": a light's direction must be a finite, non-zero vector");
          }
          event.value = glm::normalize(event.value);
        }
      }
    } else if (what == "exposure") {
      expectWords(words, 5, where, "at <frame> set exposure <stops>");
      event.action = ScriptAction::kSetExposure;
      readValues(event, words, 4, "the exposure");
      if (!(std::abs(event.value.x) <= kMaxExposureStops)) {
        throw Error(where + ": the exposure is " + words[4] + " stops; it is within [-" +
                    numberText(kMaxExposureStops) + ", " + numberText(kMaxExposureStops) + "], as --exposure");
      }
    } else if (what == "max-depth") {
      expectWords(words, 5, where, "at <frame> set max-depth <bounces>");
      event.action = ScriptAction::kSetMaxDepth;
      event.value.x = float(parseCount(words[4], where, "the depth"));
      event.valueCount = 1;
      checkCount(kMaxDepthOption, std::int64_t(event.value.x), where);
    } else if (what == "integrator") {
      expectWords(words, 5, where, "at <frame> set integrator " + choiceList(kIntegratorOption));
      event.action = ScriptAction::kSetIntegrator;
      event.param = words[4];
      choiceIndex(kIntegratorOption, event.param, where);
    } else if (what == "environment") {
      expectWords(words, 6, where, "at <frame> set environment strength|rotation <value>");
      const std::string& property = words[4];
      if (property == "strength") event.action = ScriptAction::kSetEnvironmentStrength;
      else if (property == "rotation") event.action = ScriptAction::kSetEnvironmentRotation;
      else throw Error(where + ": an environment has strength and rotation, not '" + property + "'");
      readValues(event, words, 5, "an environment value");
      if (!finiteInFloat(event.value) || (property == "strength" && event.value.x < 0.0f)) {
        throw Error(where + ": the environment's " + property + " must be finite" +
                    (property == "strength" ? " and >= 0" : ""));
      }
    } else if (what == "divider") {
      expectWords(words, 5, where, "at <frame> set divider <fraction>");
      event.action = ScriptAction::kSetDivider;
      readValues(event, words, 4, "the divider");
      if (!(event.value.x >= 0.0f && event.value.x <= 1.0f)) throw Error(where + ": the divider must be within [0, 1]");
    } else if (what == "difference") {
      if (words.size() != 5 && words.size() != 6) {
        throw Error(where + ": expected 'at <frame> set difference off|absolute|relative [<scale>]'");
      }
      event.action = ScriptAction::kSetDifference;
      event.param = words[4];
      if (event.param != "off" && event.param != "absolute" && event.param != "relative") {
        throw Error(where + ": the difference view is off, absolute or relative, not '" + event.param + "'");
      }
      readValues(event, words, 5, "the difference scale");
      if (event.valueCount == 1 && !(event.value.x > 0.0f)) throw Error(where + ": the difference scale must be > 0");
    } else {
      throw Error(where + ": 'set' takes material, light, exposure, max-depth, integrator, environment, divider or "
                  "difference, not '" + what + "'");
    }
  } else {
    throw Error(where + ": unknown action '" + action +
                "' (actions: orbit, pan, zoom, set, model, resize, screenshot, compare, pick, save, denoise)");
  }
  return event;
}

}  // namespace

std::vector<ScriptEvent> parseScript(const std::string& text, const std::string& path) {
  std::vector<ScriptEvent> events;
  std::istringstream lines(text);
  std::string line;
  for (std::uint32_t number = 1; std::getline(lines, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    const std::vector<std::string> words = splitWords(line, where);
    if (!words.empty()) events.push_back(parseLine(words, where, std::filesystem::path(path).parent_path().string()));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  return events;
}

std::vector<ScriptEvent> loadScript(const std::string& path) { return parseScript(readInputFile(path, kMaxScriptBytes), path); }

SceneEffect applyToScene(const ScriptEvent& event, Scene& scene) {
  SceneEffect effect;
  switch (event.action) {
    case ScriptAction::kSetMaterial:
    case ScriptAction::kModel: {
      Material* material = findMaterial(scene, event.name);
      if (material == nullptr) {
        std::string known;
        for (const Material& m : scene.materials) known += (known.empty() ? "'" : ", '") + m.name + "'";
        throw Error(event.where + ": the scene has no material '" + event.name + "' (materials: " + known + ")");
      }
      if (event.action == ScriptAction::kModel) {
        const ModelInfo* model = findModel(event.param);
        if (model == nullptr) {
          throw Error(event.where + ": unknown model '" + event.param + "' (models: " + modelNames() + ")");
        }
        gpu::MaterialRecord switched = material->record;
        switchModel(switched, model->id);
        const ParamInfo* file = findFileParam(*model);
        if (!event.path.empty() && file == nullptr) throw Error(event.where + ": " + std::string(model->name) + " reads no file");
        if (file != nullptr && !event.path.empty()) setFileParam(switched, file->name, event.path, event.where);
        checkFileParams(switched, event.where + " (name its file: model " + event.name + " " + event.param + " FILE)");
        material->record = switched;
      } else if (isPresetKey(modelInfo(material->record.model), event.param) && !event.word.empty()) {
        // Named presets, as everywhere else a material is given (metal=Au, "metal": "Au", metal="Au").
        applyPreset(material->record, event.param, event.word, event.where);
      } else {
        const ParamInfo* param = findParam(modelInfo(material->record.model), event.param);
        // setParam's error lists the parameters the model has.
        if (param == nullptr) setParam(material->record, event.param, glm::vec3(0.0f), event.where);
        if (isFileParam(*param) != !event.path.empty()) {
          throw Error(event.where + ": " + event.param + (event.path.empty() ? " takes a file path" : " takes numbers"));
        }
        if (isFileParam(*param)) {
          setFileParam(material->record, event.param, event.path, event.where);
          effect.materials = true;
          break;
        }
        if (event.valueCount != 1 && !(param->rgb && event.valueCount == 3)) {
          throw Error(event.where + ": " + event.param + " takes " + (param->rgb ? "1 or 3 values" : "1 value"));
        }
        const glm::vec3 value = event.valueCount == 1 ? glm::vec3(event.value.x) : event.value;
        setParam(material->record, event.param, value, event.where);
      }
      effect.materials = true;
      break;
    }
    case ScriptAction::kSetLightIntensity:
    case ScriptAction::kSetLightPosition:
    case ScriptAction::kSetLightDirection:
    case ScriptAction::kSetLightCone: {
      Light* light = findLight(scene, event.name);
      if (light == nullptr) {
        std::string known;
        for (const Light& l : scene.lights) known += (known.empty() ? "'" : ", '") + l.name + "'";
        throw Error(event.where + ": the scene has no light '" + event.name + "' (lights: " + known + ")");
      }
      const std::uint32_t type = light->record.type;
      if (event.action == ScriptAction::kSetLightIntensity) {
        light->record.intensity = event.value;
      } else if (event.action == ScriptAction::kSetLightPosition) {
        light->record.position = event.value;
      } else if (event.action == ScriptAction::kSetLightDirection) {
        if (type != gpu::kLightSpot && type != gpu::kLightDirectional) {
          throw Error(event.where + ": light '" + event.name + "' is a point light, which has no direction");
        }
        light->record.direction = event.value;
      } else {
        if (type != gpu::kLightSpot) throw Error(event.where + ": light '" + event.name + "' is not a spot light");
        light->record.cosInner = std::cos(glm::radians(event.value.x));
        light->record.cosOuter = std::cos(glm::radians(event.value.y));
      }
      effect.lights = true;
      break;
    }
    case ScriptAction::kSetEnvironmentStrength:
    case ScriptAction::kSetEnvironmentRotation:
      if (!scene.environment.hasImage()) {
        throw Error(event.where + ": the scene has no environment image (give one with --env FILE.exr)");
      }
      if (event.action == ScriptAction::kSetEnvironmentStrength) {
        checkEnvironmentStrength(scene.environment, event.value.x, event.where);
        scene.environment.strength = event.value.x;
      } else {
        scene.environment.rotation = glm::radians(event.value.x);
      }
      break;
    case ScriptAction::kCompare:
      if (event.name != "off") parseCompareSpec(event.name, scene, event.where);
      break;
    default:
      break;
  }
  return effect;
}

void checkScript(const std::vector<ScriptEvent>& events, const Scene& original) {
  Scene scene = original;  // model switches earlier in the script decide which parameters exist later
  for (const ScriptEvent& event : events) applyToScene(event, scene);
}

bool resetsAccumulation(const ScriptEvent& event) {
  switch (event.action) {
    case ScriptAction::kScreenshot:
    case ScriptAction::kSetExposure:
    case ScriptAction::kSetDivider:
    case ScriptAction::kSetDifference:
    case ScriptAction::kPick:
    case ScriptAction::kSaveLobe:
    case ScriptAction::kDenoise:
      return false;
    default:
      return true;
  }
}

}  // namespace raylab
