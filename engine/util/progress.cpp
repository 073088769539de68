#include "util/progress.h"

#include <unistd.h>

#include <cmath>

namespace raylab {

ProgressLine::ProgressLine(std::string label, std::uint64_t total, std::FILE* stream, std::string unit)
    : label_(std::move(label)), total_(total), unit_(std::move(unit)), stream_(stream),
      interactive_(isatty(fileno(stream)) != 0) {}

void ProgressLine::update(std::uint64_t done, std::uint64_t raysSoFar) {
  const double elapsed = clock_.seconds();
  const double interval = interactive_ ? 0.1 : 5.0;
  if (done < total_ && lastPrint_ >= 0.0 && elapsed - lastPrint_ < interval) return;
  lastPrint_ = elapsed;
  const double steady = elapsed - warmupSeconds_;
  const double raysPerSecond = steady > 0.0 ? static_cast<double>(raysSoFar - warmupRays_) / steady : 0.0;
  print(done, elapsed, formatCount(raysPerSecond, "rays/s"));
}

void ProgressLine::warmedUp(std::uint64_t done, std::uint64_t raysSoFar) {
  warmupSeconds_ = clock_.seconds();
  warmupRays_ = raysSoFar;
  lastPrint_ = warmupSeconds_;
  print(done, warmupSeconds_, "(first sample: kernel compilation included)");
}

void ProgressLine::print(std::uint64_t done, double elapsed, const std::string& tail) {
  std::fprintf(stream_, "%s%s %llu/%llu %s  %s  %s%s", interactive_ ? "\r" : "", label_.c_str(),
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_), unit_.c_str(),
               formatSeconds(elapsed).c_str(), tail.c_str(), interactive_ ? "\x1b[K" : "\n");
  std::fflush(stream_);
  printedAny_ = true;
}

void ProgressLine::finish() {
  if (interactive_ && printedAny_) std::fputc('\n', stream_);
  std::fflush(stream_);
}

std::string formatCount(double count, const char* unit) {
  char text[64];
  if (count >= 1e9) std::snprintf(text, sizeof text, "%.2f G%s", count / 1e9, unit);
  else if (count >= 1e6) std::snprintf(text, sizeof text, "%.2f M%s", count / 1e6, unit);
  else if (count >= 1e3) std::snprintf(text, sizeof text, "%.1f k%s", count / 1e3, unit);
  else std::snprintf(text, sizeof text, "%.0f%s%s", count, unit[0] != '\0' ? " " : "", unit);
  return text;
}

std::string formatSeconds(double seconds) {
  char text[32];
  if (seconds >= 1.0) std::snprintf(text, sizeof text, "%.2f s", seconds);
  else if (seconds >= 1e-3) std::snprintf(text, sizeof text, "%.1f ms", seconds * 1e3);
  else std::snprintf(text, sizeof text, "%.0f us", seconds * 1e6);
  return text;
}

}  // namespace raylab
