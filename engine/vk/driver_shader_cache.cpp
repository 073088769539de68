#include "vk/driver_shader_cache.h"

#include <cstdlib>
#include <mutex>
#include <string>

namespace raylab {

namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

// Mesa's choice of cache folder (util/disk_cache_os.c): MESA_SHADER_CACHE_DIR, else $XDG_CACHE_HOME, else
// $HOME/.cache; it adds its own "mesa_shader_cache" below whichever it takes.
std::string mesaCacheParent() {
  for (const char* name : {"MESA_SHADER_CACHE_DIR", "XDG_CACHE_HOME"}) {
    const std::string value = environment(name);
    if (!value.empty()) return value;
  }
  const std::string home = environment("HOME");
  return home.empty() ? std::string() : home + "/.cache";
}

// A folder name from a setting's value: its letters and digits, so that no value can name a path.
std::string folderPart(const std::string& value) {
  std::string part;
  for (const char c : value) {
    const bool plain = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    part += plain ? c : '_';
  }
  return part.substr(0, 32);
}

}  // namespace

void separateShaderCacheByDriverSettings() {
  static std::once_flag once;
  std::call_once(once, [] {
    const std::string width = environment("LP_NATIVE_VECTOR_WIDTH");
    const std::string perf = environment("GALLIVM_PERF");
    if (width.empty() && perf.empty()) return;
    const std::string parent = mesaCacheParent();
    if (parent.empty()) return;  // Mesa finds no cache folder either and caches nothing
    const std::string folder = parent + "/raylab-lavapipe-width" + folderPart(width.empty() ? "default" : width) +
                               "-perf" + folderPart(perf.empty() ? "default" : perf);
    setenv("MESA_SHADER_CACHE_DIR", folder.c_str(), 1);
  });
}

}  // namespace raylab
