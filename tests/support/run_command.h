// Runs the raylab executable (or any command) the way a user would, capturing its output and exit code.
#pragma once

#include <string>
#include <vector>

namespace raylab::test {

struct CommandResult {
  int exitCode = -1;   // -1: killed by a signal (a crash)
  std::string output;  // stdout and stderr interleaved
};

// `environment` entries ("NAME=value") are added to the current environment; "NAME=" sets it empty.
// `workingDirectory`: where the command runs (empty: here); raylab creates output directories only below it.
CommandResult runCommand(const std::vector<std::string>& arguments,
                         const std::vector<std::string>& environment = {}, const std::string& workingDirectory = "");

// Runs the raylab binary of this build with `arguments`.
CommandResult runRaylab(const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {},
                        const std::string& workingDirectory = "");

}  // namespace raylab::test
