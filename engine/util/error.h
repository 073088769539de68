// The error type every raylab failure travels as, and the process exit codes the CLI maps it to.
#pragma once

#include <stdexcept>
#include <string>

namespace raylab {

enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,   // bad input file, I/O error, Vulkan failure
  kExitUsage = 2,     // bad command line
  kExitNoDevice = 3,  // no Vulkan device that can run raylab
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, ExitCode exitCode = kExitFailure)
      : std::runtime_error(message), exitCode_(exitCode) {}
  ExitCode exitCode() const { return exitCode_; }

 private:
  ExitCode exitCode_;
};

}  // namespace raylab
