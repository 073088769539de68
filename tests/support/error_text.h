// The message of the raylab Error a call throws, or "" when it throws none: what the bad-input tests read.
#pragma once

#include <functional>
#include <string>

#include "util/error.h"

namespace raylab::test {

inline std::string errorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace raylab::test
