#pragma once

// RAYLAB_KERNEL_LOG=FILE appends a line per pipeline the process creates: seconds spent in the driver, the
// kernel's name, a digest of its specialised SPIR-V and constants, the LLVM setting and the process. Kernel
// compilation is most of a cold test suite's time on lavapipe; this is how to see which kernels cost it and
// which tests compile the same one twice (docs/architecture.md, "The test suite's time", sums it per test).

#include <chrono>
#include <cstdint>
#include <span>
#include <string_view>

namespace raylab {

// The log's file, or nullptr when RAYLAB_KERNEL_LOG is unset: callers skip the digest's work then.
const char* kernelLogPath();

// FNV-1a over the words, continuing from `digest`: a kernel's SPIR-V, then its specialisation data.
std::uint64_t kernelDigest(std::span<const std::uint32_t> words, std::uint64_t digest = 1469598103934665603ull);

void logKernelCompilation(std::string_view kernelName, std::uint64_t digest, std::chrono::steady_clock::duration spent);

}  // namespace raylab
