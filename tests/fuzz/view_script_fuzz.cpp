// libFuzzer target: the viewer's script parser and its check against a scene (the built-in showcase).
#include <cstddef>
#include <cstdint>
#include <string>

#include "builtin_scenes/default_scene.h"
#include "util/error.h"
#include "util/log.h"
#include "view_logic/script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const raylab::Scene scene = [] {
    raylab::setWarningSink([](const std::string&) {});
    return raylab::makeDefaultScene();
  }();
  try {
    const auto events = raylab::parseScript(std::string(reinterpret_cast<const char*>(data), size), "fuzz.txt");
    raylab::checkScript(events, scene);
  } catch (const raylab::Error&) {
  }
  return 0;
}
