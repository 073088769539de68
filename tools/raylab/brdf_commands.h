// The commands below `raylab brdf` that live outside cmd_brdf.cpp.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

void addBrdfAlbedoCommand(CLI::App& brdf);
// `raylab brdf models` (brdf_models.cpp).
void addBrdfModelsCommand(CLI::App& brdf);

}  // namespace raylab
