// Wall-clock seconds since construction, and CPU seconds of the whole process.
#pragma once

#include <time.h>

#include <chrono>

namespace raylab {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  void restart() { start_ = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

// CPU time of every thread of this process (lavapipe's and Embree's workers run in-process) since
// construction. On a machine shared with other work it varies far less than wall-clock time, which makes
// it the better measure when comparing two versions of a kernel.
class CpuStopwatch {
 public:
  CpuStopwatch() : start_(now()) {}
  double seconds() const { return now() - start_; }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  double start_;
};

}  // namespace raylab
