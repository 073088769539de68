// Intel Open Image Denoise (Áfra et al.) on a rendered image: `raylab render --denoise` and the viewer's denoised
// view (docs/denoising.md). The library is loaded at the first call (denoise/oidn_library.h).
#pragma once

#include <string>
#include <string_view>

#include "image/image.h"

namespace raylab {

// In the order of kDenoiseQualityValues (util/render_options.h), where the names are declared.
enum class DenoiseQuality { kFast, kBalanced, kHigh };

// The quality named `name`; throws Error(kExitUsage) naming `where` and the values otherwise.
DenoiseQuality parseDenoiseQuality(std::string_view name, const std::string& where);

// The denoised colour, the same size, alpha 1. `color` is HDR radiance; `aux`, when given, has images of the same
// size. Throws Error(kExitUsage) when Open Image Denoise cannot be loaded, saying how to install it, and Error for a
// size mismatch, a non-finite input or a failure of the library (its message). Thread-safe: calls take turns on one
// device, and a call of the last call's size and quality reuses its filter.
Image denoise(const Image& color, const AuxiliaryImages* aux, DenoiseQuality quality = DenoiseQuality::kHigh);

// Loads the library now: for a command to refuse --denoise before it spends time rendering. Returns its path.
std::string loadDenoiser();

}  // namespace raylab
