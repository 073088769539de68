#include "util/log.h"

#include <cstdio>
#include <utility>

namespace raylab {

namespace {

WarningSink& currentSink() {
  static WarningSink sink;
  return sink;
}

}  // namespace

void warn(const std::string& message) {
  if (currentSink()) {
    currentSink()(message);
    return;
  }
  std::fprintf(stderr, "raylab: warning: %s\n", message.c_str());
}

WarningSink setWarningSink(WarningSink sink) { return std::exchange(currentSink(), std::move(sink)); }

}  // namespace raylab
