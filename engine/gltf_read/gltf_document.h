// Internal to the glTF loader: a parsed file (tinygltf's model next to the raw JSON, from which extras and
// extensions are read) and what its conversion reports. Messages start with the file, so a user with
// several files open knows which one is at fault.
#pragma once

#include <initializer_list>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "gltf_read/gltf_files.h"

namespace raylab::gltf {

struct Document {
  std::string label;    // the path, or the scene name of text loaded from memory
  nlohmann::json json;  // the whole glTF JSON, schema-checked (gltf_schema.cpp)
  tinygltf::Model model;
  std::string baseDirectory;  // external URIs resolve against it, under uriPolicy
  UriPolicy uriPolicy;
  std::set<std::string> ignored;  // features raylab does not support, reported in one warning at the end
  std::set<std::string> warned;   // keys of warnings already given, so each kind is given once per file

  // Throws Error("<label>: <message>").
  [[noreturn]] void fail(const std::string& message) const;
  // Gives `message` (prefixed with the label) unless a warning with the same key was given already.
  void warnOnce(const std::string& key, const std::string& message);
  void ignore(const std::string& feature) { ignored.insert(feature); }
  // After the conversion: one warning listing everything in `ignored`.
  void reportIgnored() const;
};

// Reads a .glb or .gltf from memory: the GLB container, the JSON (with its line and column on a syntax
// error, and its nesting depth), the schema check, the required extensions, then tinygltf (buffers and data
// URIs; images stay encoded until a material uses them, gltf_files.h). External files must lie inside
// `baseDirectory` unless `allowOutsideUris`. Extensions in extensionsUsed that raylab does not read go to
// `ignored`. `label` starts messages.
Document parseDocument(const std::string& bytes, const std::string& baseDirectory, const std::string& label,
                       bool mustBeBinary, bool allowOutsideUris);

// Checks the JSON types of every property the loader reads, so that a string where a number belongs is an
// error naming its JSON path instead of a silently defaulted value (tinygltf 2.7 ignores most wrong types).
void checkSchema(const nlohmann::json& root, const std::string& label);

// "node 3 'wheel'", "material 0", ...: how messages name an element of a top-level array.
std::string describe(std::string_view kind, int index, const std::string& name);

// The value at `path` of nested objects (extras, extensions), or null when any step is missing.
const nlohmann::json* findPath(const nlohmann::json& object, std::initializer_list<const char*> path);

// A JSON value as messages quote it, shortened to 40 characters.
std::string quote(const nlohmann::json& value);

// A number as messages print it (%g).
std::string formatNumber(double value);

}  // namespace raylab::gltf
