// libFuzzer target: the measured targets of `raylab brdf fit`: a MERL phi_d = 90 slice (an input of exactly a slice's
// size) and the CSV of samples with its optional weight column (any other input). Bad input is reported, never fatal.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fit/fit_target.h"
#include "fit/merl_slice.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    if (size == raylab::kSliceBytes) {
      raylab::decodeMerlSlice(std::string(text), "fuzz.slice");
    } else {
      raylab::parseFitCsv(text, "fuzz.csv");
    }
  } catch (const raylab::Error&) {
  }
  return 0;
}
