// Host-side lookup of the SPIR-V kernels compiled at build time and embedded in the binary.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace raylab {

// Words of the kernel compiled from shaders/<kernelName> (e.g. "render.comp"); empty if there is none.
std::span<const std::uint32_t> embeddedSpirv(std::string_view kernelName);

}  // namespace raylab
