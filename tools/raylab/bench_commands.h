// The commands below `raylab bench` that live outside cmd_bench.cpp.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

void addBenchRaysCommand(CLI::App& bench);
void addBenchOrderCommand(CLI::App& bench);
void addBenchViewCommand(CLI::App& bench);

}  // namespace raylab
