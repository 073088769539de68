// raylab's subcommands. Each parses its own arguments (argv starts after the command name) and returns the
// process exit code; errors travel as raylab::Error.
#pragma once

namespace raylab {

int runRender(int argc, char** argv);
int runDevices(int argc, char** argv);
int runBench(int argc, char** argv);
int runView(int argc, char** argv);
int runBrdf(int argc, char** argv);
int runSweep(int argc, char** argv);

}  // namespace raylab
