// raylab's command line on CLI11: the command tree, options with raylab's conventions (ranges and choices checked
// on the spot, finite numbers, defaults shown in the help, descriptions wrapped), and the option groups several
// commands share, each declared once here. Usage errors exit 2 with a message naming the option.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene/load_scene.h"

namespace raylab {

// The root app, with raylab's help formatter.
std::unique_ptr<CLI::App> makeCommandLine();

// A command below `parent`: `run` is called when it was the one given and returns the exit code (errors travel
// as raylab::Error). The description's first line is its summary in the parent's list.
CLI::App* addCommand(CLI::App& parent, const std::string& name, const std::string& description,
                     std::function<int()> run);
// A group of commands (`raylab brdf`, `raylab bench`): one of its commands must be given.
CLI::App* addCommandGroup(CLI::App& parent, const std::string& name, const std::string& description);

// The deepest command given on the command line, and its path ("raylab brdf eval"): errors carry the path.
const CLI::App* deepestCommand(const CLI::App& app, std::string& path);

// Parses and runs the command given; returns the exit code (2 for usage errors, 0 after --help).
int runCommandLine(CLI::App& app, int argc, char** argv);

// Options. Each shows its default (the variable's value when declared) and its range in the help.
CLI::Option* addFlag(CLI::App* command, const std::string& name, bool& value, const std::string& help);
CLI::Option* addText(CLI::App* command, const std::string& name, std::string& value, const std::string& metavar,
                     const std::string& help);
CLI::Option* addCount(CLI::App* command, const std::string& name, std::uint32_t& value, const std::string& help,
                      std::uint32_t min, std::uint32_t max);
CLI::Option* addNumber(CLI::App* command, const std::string& name, float& value, const std::string& help, float min,
                       float max);
CLI::Option* addOptionalNumber(CLI::App* command, const std::string& name, std::optional<float>& value,
                               const std::string& help, float min, float max);
CLI::Option* addChoice(CLI::App* command, const std::string& name, std::string& value,
                       const std::vector<std::string>& choices, const std::string& help);
CLI::Option* addPositional(CLI::App* command, const std::string& name, std::string& value, const std::string& help);

// The names options take, as the kernels and images use them.
ToneMap parseToneMap(const std::string& name);
IntegratorChoice parseIntegratorChoice(const std::string& name);
// Throws Error(kExitUsage) "<command>: <option>: 'path' must end in <extension>".
void requireExtension(const std::string& command, const std::string& option, const std::string& path,
                      const std::string& extension);

// The groups several commands share.
// SCENE (positional), --camera, --allow-outside-uris, --env, --env-strength, --env-rotation.
void addSceneOptions(CLI::App* command, SceneRequest& request);
// --integrator auto|slides|path.
void addIntegratorOption(CLI::App* command, std::string& integrator);
// --seed and --max-depth.
void addSampleOptions(CLI::App* command, RenderSettings& settings);
// --exposure and --tonemap of an 8-bit image (`what`: "the PNG", "the display").
void addToneOptions(CLI::App* command, float& exposure, std::string& toneMap, const std::string& what);
void addDeviceOption(CLI::App* command, std::optional<std::uint32_t>& device);
// --width and --height in [minSide, kMaxImageSide].
void addImageSizeOptions(CLI::App* command, std::uint32_t& width, std::uint32_t& height, const std::string& what,
                         std::uint32_t minSide = 1);
// --backend auto|query|pipeline, and the benchmarks' version with `all` (every backend the device has).
void addBackendOption(CLI::App* command, std::string& backend);
void addBenchBackendOption(CLI::App* command, std::string& backend);

}  // namespace raylab
