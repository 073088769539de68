// libFuzzer target: an environment image (OpenEXR, decoded by the OpenEXR library) as raylab reads one, through
// its checks and the importance-sampling tables. Bad files are reported, never fatal.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/environment.h"
#include "scene/environment_tables.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const raylab::Environment environment =
        raylab::decodeEnvironment(std::string(reinterpret_cast<const char*>(data), size), "fuzz.exr");
    raylab::buildEnvironmentTables(environment);
  } catch (const raylab::Error&) {
  }
  return 0;
}
