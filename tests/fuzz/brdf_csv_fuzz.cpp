// libFuzzer target: the BRDF case CSV parser of `raylab brdf eval`. Malformed rows are reported, never fatal.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "brdf_eval/brdf_cases.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    raylab::parseBrdfCases(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
  } catch (const raylab::Error&) {
  }
  return 0;
}
