// The ranges of a render's options that more than one entry point checks (the command line, the viewer's
// script and panel, Python, the farm), each stated once.
#pragma once

#include <cstdint>

namespace raylab {

// The most samples per pixel one image accumulates (--spp, --spp-limit, Python's render and add_samples):
// float sums of more would stop changing.
inline constexpr std::uint32_t kMaxSamplesPerPixel = 1u << 20;
// The most bounces after the primary hit (--max-depth, the viewer's script, Python, the farm).
inline constexpr std::uint32_t kMaxDepthLimit = 64;

}  // namespace raylab
