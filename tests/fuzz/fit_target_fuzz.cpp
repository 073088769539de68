// libFuzzer target: the measured targets of `raylab brdf fit`: a MERL phi_d = 90 slice and the CSV of samples with
// its optional weight column. Bad input is reported, never fatal. An input that starts with "slice:" is a slice
// whose bytes are the rest repeated to a slice's size (the committed seeds stay a few bytes, and no file of
// measured-data size is tracked); an input of exactly a slice's size is a slice as it is; any other is a CSV.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fit/fit_target.h"
#include "fit/merl_slice.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSlicePrefix = "slice:";
  try {
    if (text.starts_with(kSlicePrefix)) {
      const std::string_view pattern = text.substr(kSlicePrefix.size());
      std::string bytes(raylab::kSliceBytes, '\0');
      for (std::size_t i = 0; !pattern.empty() && i < bytes.size(); ++i) bytes[i] = pattern[i % pattern.size()];
      raylab::decodeMerlSlice(bytes, "fuzz.slice");
    } else if (size == raylab::kSliceBytes) {
      raylab::decodeMerlSlice(std::string(text), "fuzz.slice");
    } else {
      raylab::parseFitCsv(text, "fuzz.csv");
    }
  } catch (const raylab::Error&) {
  }
  return 0;
}
