// A progress line for long work: samples done, elapsed time and ray throughput. On a terminal it redraws
// one line; in a log (CI, pipes) it prints a line every few seconds so the log stays short.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "util/timer.h"

namespace raylab {

class ProgressLine {
 public:
  // `unit` names what is counted: samples per pixel ("spp"), or a sweep's samples over all its cells.
  ProgressLine(std::string label, std::uint64_t total, std::FILE* stream = stderr, std::string unit = "spp");
  void update(std::uint64_t done, std::uint64_t raysSoFar);
  // Work done so far was a warm-up (the first sample, which waits for the driver's kernel compilation): it is
  // printed as such now, and later lines give the rate of what follows it alone.
  void warmedUp(std::uint64_t done, std::uint64_t raysSoFar);
  void finish();

 private:
  // One line: "LABEL done/total UNIT  ELAPSED  tail", redrawn in place on a terminal.
  void print(std::uint64_t done, double elapsed, const std::string& tail);

  std::string label_;
  std::uint64_t total_;
  std::string unit_;
  std::FILE* stream_;
  bool interactive_;
  Stopwatch clock_;
  double lastPrint_ = -1.0;
  bool printedAny_ = false;
  std::uint64_t warmupRays_ = 0;
  double warmupSeconds_ = 0.0;
};

// Counts for humans with an SI prefix glued to the unit: "12.3 Mrays/s", "456 krays", "12 rays".
std::string formatCount(double count, const char* unit);
// "1.52 s", "48.2 ms", "310 us".
std::string formatSeconds(double seconds);

}  // namespace raylab
