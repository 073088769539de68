// The commands below `raylab brdf` that live outside cmd_brdf.cpp.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

void addBrdfAlbedoCommand(CLI::App& brdf);
// `raylab brdf models` (brdf_models.cpp).
void addBrdfModelsCommand(CLI::App& brdf);
// `raylab brdf fit` (brdf_fit.cpp).
void addBrdfFitCommand(CLI::App& brdf);
// `raylab brdf tabulate` (brdf_tabulate.cpp).
void addBrdfTabulateCommand(CLI::App& brdf);

}  // namespace raylab
