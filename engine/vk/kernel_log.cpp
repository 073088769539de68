#include "vk/kernel_log.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace raylab {

namespace {

std::string processName() {
  std::ifstream comm("/proc/self/comm");
  std::string name;
  std::getline(comm, name);
  return name.empty() ? "?" : name;
}

}  // namespace

const char* kernelLogPath() {
  const char* path = std::getenv("RAYLAB_KERNEL_LOG");
  return path != nullptr && *path != '\0' ? path : nullptr;
}

std::uint64_t kernelDigest(std::span<const std::uint32_t> words, std::uint64_t digest) {
  for (const std::uint32_t word : words) {
    for (int byte = 0; byte < 4; ++byte) {
      digest ^= (word >> (8 * byte)) & 0xffu;
      digest *= 1099511628211ull;
    }
  }
  return digest;
}

void logKernelCompilation(std::string_view kernelName, std::uint64_t digest, std::chrono::steady_clock::duration spent) {
  const char* path = kernelLogPath();
  if (path == nullptr) return;
  const char* perf = std::getenv("GALLIVM_PERF");
  char line[512];
  const int length = std::snprintf(line, sizeof line, "%.3f\t%.*s\t%016llx\t%s\t%s\t%d\n",
                                   std::chrono::duration<double>(spent).count(), static_cast<int>(kernelName.size()),
                                   kernelName.data(), static_cast<unsigned long long>(digest),
                                   perf != nullptr && *perf != '\0' ? perf : "default", processName().c_str(),
                                   static_cast<int>(getpid()));
  if (length <= 0) return;
  // One write with O_APPEND: lines from tests running side by side do not interleave. O_NONBLOCK: a FIFO nobody
  // reads makes the open fail instead of hanging the render.
  const int file = open(path, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | O_NONBLOCK, 0644);
  if (file < 0) return;
  [[maybe_unused]] const ssize_t written = write(file, line, static_cast<std::size_t>(std::min(length, 511)));
  close(file);
}

}  // namespace raylab
