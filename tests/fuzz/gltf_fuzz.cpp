// libFuzzer target: the glTF/GLB loader on arbitrary bytes. Any raylab::Error is a correct answer; a crash,
// a sanitizer report, a hang or memory beyond libFuzzer's -rss_limit_mb is a bug. External URIs are refused
// (no base directory), so the loader reads nothing but the input.
#include <cstddef>
#include <cstdint>
#include <string>

#include "gltf_read/gltf_loader.h"
#include "util/error.h"
#include "util/log.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = (raylab::setWarningSink([](const std::string&) {}), true);
  (void)quiet;
  try {
    raylab::loadGltfText(std::string(reinterpret_cast<const char*>(data), size), "", "fuzz", {});
  } catch (const raylab::Error&) {
  }
  return 0;
}
