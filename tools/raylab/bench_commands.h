// The commands below `raylab bench` that live outside cmd_bench.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace raylab {

void addBenchRaysCommand(CLI::App& bench);
void addBenchOrderCommand(CLI::App& bench);
void addBenchViewCommand(CLI::App& bench);

}  // namespace raylab
