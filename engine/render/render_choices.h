// The named values of the render options (util/render_options.h) as the renderer's enums: where a string from the
// command line, Python, the farm or a viewer script becomes a value, once. Each throws Error (kExitUsage) naming
// `where`, the option and its values for a value that is not one of them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "render/backend.h"
#include "render/kernel_features.h"
#include "render/path_guide.h"
#include "render/wavefront.h"

namespace raylab {

IntegratorChoice parseIntegratorChoice(std::string_view value, const std::string& where);
std::uint32_t parseSampling(std::string_view value, const std::string& where);  // gpu::kSampling...
bool parseSchlickFresnel(std::string_view value, const std::string& where);
Schedule parseSchedule(std::string_view value, const std::string& where);
BackendChoice parseBackendChoice(std::string_view value, const std::string& where);
Guiding parseGuiding(std::string_view value, const std::string& where);

}  // namespace raylab
