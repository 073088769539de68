// The commands below `raylab brdf` that live outside cmd_brdf.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace raylab {

void addBrdfAlbedoCommand(CLI::App& brdf);

}  // namespace raylab
