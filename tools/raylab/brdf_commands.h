// The subcommands behind `raylab brdf <name>` that live outside cmd_brdf.cpp; each parses its own arguments.
#pragma once

namespace raylab {

int runBrdfAlbedo(int argc, char** argv);

}  // namespace raylab
