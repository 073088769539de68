// Specialises a kernel's SPIR-V on the host, before the driver sees it. The kernels hold every model, light kind
// and feature of the library, each behind a specialization constant (shaders/common/specialization.glsl). A
// driver removes the unused ones only after translating and inlining all of them: lavapipe spent a third of a
// second per kernel on code a scene never runs, on every pipeline it built, cached or not, and the cost grew with
// each model added. Here the constants are set and frozen, and the branches and functions they rule out are
// removed (SPIRV-Tools' optimizer, a few tens of milliseconds), so a scene's kernel holds only what it uses.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab {

// `spirv` with each (constant id, value) of `constants` as its specialization constant's value, frozen, and the
// code that the frozen values make unreachable removed. Throws Error naming `kernelName` if the optimizer fails.
std::vector<std::uint32_t> specializeSpirv(std::span<const std::uint32_t> spirv,
                                           std::span<const std::pair<std::uint32_t, std::uint32_t>> constants,
                                           std::string_view kernelName);

}  // namespace raylab
