// libFuzzer target: a neural BRDF's files (engine/measured/nbrdf.h), the HDF5 weights through Debian's libhdf5 and the
// Keras architecture JSON. Bad input is reported, never fatal. An input that starts with '{' is the architecture up to
// its first NUL byte and the weights after it; any other input is the weights, with the published architecture.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "measured/nbrdf.h"
#include "util/error.h"

namespace {

// The published architecture (Sztrajman et al.'s .json, reduced to what the reader checks).
constexpr std::string_view kArchitecture =
    R"({"class_name": "Sequential", "config": {"name": "sequential_1", "layers": [)"
    R"({"class_name": "Dense", "config": {"name": "dense_1", "batch_input_shape": [null, 6], "units": 21, )"
    R"("activation": "relu", "use_bias": true}}, )"
    R"({"class_name": "Dense", "config": {"name": "dense_2", "units": 21, "activation": "relu", "use_bias": true}}, )"
    R"({"class_name": "Dense", "config": {"name": "dense_3", "units": 3, "activation": "linear", "use_bias": true}}, )"
    R"({"class_name": "Lambda", "config": {"name": "lambda_1"}}]}})";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::string_view architecture = kArchitecture, weights = input;
  if (input.starts_with('{')) {
    const std::size_t end = input.find('\0');
    architecture = input.substr(0, end);
    weights = end == std::string_view::npos ? std::string_view() : input.substr(end + 1);
  }
  try {
    const raylab::NbrdfNetwork network = raylab::decodeNbrdf(std::string(weights), std::string(architecture), "fuzz.h5");
    raylab::nbrdfEval(network, {0.0, 0.6, 0.8}, {0.0, -0.6, 0.8});
  } catch (const raylab::Error&) {
  }
  return 0;
}
