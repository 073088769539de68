// raylab's commands on the command line (cli.h): each adds itself, its options and what it runs to the tree.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

void addRenderCommand(CLI::App& raylab);
void addSweepCommand(CLI::App& raylab);
void addViewCommand(CLI::App& raylab);
void addBrdfCommands(CLI::App& raylab);
void addBenchCommands(CLI::App& raylab);
void addDevicesCommand(CLI::App& raylab);
void addInfoCommand(CLI::App& raylab);

}  // namespace raylab
