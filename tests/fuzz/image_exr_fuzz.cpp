// libFuzzer target: an OpenEXR image as `raylab.read_exr`, the farm's sheet assembly and the tests read one
// (decodeExr with its default bound): channels chosen, windows placed, the header believed only as far as the
// file's content can hold it. Bad files are reported, never fatal.
#include <cstddef>
#include <cstdint>
#include <string>

#include "image/image.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const raylab::Image image = raylab::decodeExr(std::string(reinterpret_cast<const char*>(data), size), "fuzz.exr");
    if (image.rgba.size() != std::size_t(image.width) * image.height * 4) __builtin_trap();
  } catch (const raylab::Error&) {
  }
  return 0;
}
