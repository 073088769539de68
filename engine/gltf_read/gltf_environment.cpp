#include "gltf_read/gltf_environment.h"

#include <cmath>

#include <glm/glm.hpp>

#include "util/error.h"

namespace raylab::gltf {

namespace {

using nlohmann::json;

// What the file says: the image's path (resolved under the scene's URI policy), strength and rotation.
struct EnvironmentEntry {
  std::string path;
  double strength = 1.0;
  double rotation = 0.0;  // degrees about +Y
};

double readNumber(const json& value, const std::string& where, double low, double high, const char* expected) {
  if (!value.is_number()) throw Error(where + ": expected a number, found " + quote(value));
  const double number = value.get<double>();
  if (!(number >= low && number <= high)) throw Error(where + ": expected " + expected + ", found " + quote(value));
  return number;
}

EnvironmentEntry readEntry(Document& document, const json& value, const std::string& where, bool uriReplaced) {
  if (!value.is_object()) {
    throw Error(where + ": expected {\"uri\": ..., \"strength\": ..., \"rotation\": ...}, found " + quote(value));
  }
  EnvironmentEntry entry;
  std::string uri;
  for (const auto& [field, v] : value.items()) {
    if (field == "uri") {
      if (!v.is_string()) throw Error(where + ".uri: expected a string, found " + quote(v));
      uri = v.get<std::string>();
    } else if (field == "strength") {
      entry.strength = readNumber(v, where + ".strength", 0.0, 3.4e38, "a finite number >= 0");
    } else if (field == "rotation") {
      entry.rotation = readNumber(v, where + ".rotation", -kMaxEnvironmentRotationDegrees, kMaxEnvironmentRotationDegrees,
                                  "degrees in [-360, 360]");
    } else {
      throw Error(where + ": unknown key '" + field + "' (an environment has uri, strength and rotation)");
    }
  }
  if (uriReplaced) return entry;  // --env names the image: the file's uri is not read
  if (uri.empty()) throw Error(where + ": has no uri");
  try {
    entry.path = resolveUri(uri, document.baseDirectory, document.uriPolicy);
  } catch (const Error& e) {
    throw Error(where + ".uri: " + e.what());
  }
  return entry;
}

}  // namespace

Environment readEnvironment(Document& document, const GltfOptions& options) {
  std::string where = document.label + ": extras.raylab.environment";
  EnvironmentEntry entry;
  if (const json* raylab = findPath(document.json, {"extras", "raylab"})) {
    const std::string root = document.label + ": extras.raylab";
    if (!raylab->is_object()) throw Error(root + ": expected an object, found " + quote(*raylab));
    for (const auto& [key, value] : raylab->items()) {
      if (key != "environment") {
        throw Error(root + ": unknown key '" + key + "' (the file's extras.raylab has environment; background "
                    "belongs to a scene's extras.raylab)");
      }
      entry = readEntry(document, value, where, !options.environment.empty());
    }
  }
  if (!options.environment.empty()) {
    entry.path = options.environment;
    where = "--env";
  }
  const auto needsImage = [&](const char* option) {
    if (entry.path.empty()) {
      throw Error(std::string(option) + ": the scene has no environment image (give one with --env FILE.exr)",
                  kExitUsage);
    }
  };
  if (options.environmentStrength) {
    entry.strength = *options.environmentStrength;
    if (!(entry.strength >= 0.0) || !std::isfinite(entry.strength)) {
      throw Error("--env-strength: environment strength must be a finite number >= 0", kExitUsage);
    }
    needsImage("--env-strength");
  }
  if (options.environmentRotation) {
    // The command line's range, for every entry point (Python's Scene.load took NaN and 1e30: a black sky).
    entry.rotation = *options.environmentRotation;
    if (!(std::abs(entry.rotation) <= kMaxEnvironmentRotationDegrees)) {
      throw Error("--env-rotation (Python: env_rotation_deg): the rotation must be a number of degrees within "
                  "[-360, 360]", kExitUsage);
    }
    needsImage("--env-rotation");
  }
  if (entry.path.empty()) return {};
  Environment environment = loadEnvironment(entry.path, float(entry.strength), where,
                                            options.environmentStrength ? "--env-strength" : where + ".strength",
                                            options.maxBufferBytes);
  environment.rotation = glm::radians(float(entry.rotation));
  return environment;
}

}  // namespace raylab::gltf
