// raylab's command line on CLI11: the command tree, options with raylab's conventions (ranges and choices checked
// on the spot, finite numbers, defaults shown in the help, descriptions wrapped), and the option groups several
// commands share, each declared once here. Usage errors exit 2 with a message naming the option.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "builtin_scenes/load_scene.h"

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

// A command below `parent`: `run` is called when it was the one given and returns the exit code (errors travel
// as raylab::Error). The description's first line is its summary in the parent's list.
CLI::App* addCommand(CLI::App& parent, const std::string& name, const std::string& description,
                     std::function<int()> run);
// A group of commands (`raylab brdf`, `raylab bench`): one of its commands must be given.
CLI::App* addCommandGroup(CLI::App& parent, const std::string& name, const std::string& description);

// Builds the command tree (`addCommands` adds raylab's commands to the root), parses argv and runs the command
// given. Returns the exit code: 2 for usage errors, 0 after --help, the command's own otherwise; errors (as
// raylab::Error) are printed with the command's name, "raylab render: ...".
int runCommandLine(int argc, char** argv, const std::function<void(CLI::App&)>& addCommands);

// Parses `arguments` as the options of command `path` ("raylab sweep"), declared by `addOptions`, without running
// anything: for callers that take a command's options themselves (the Python farm takes `raylab sweep`'s). Returns
// the command's help when --help was given, empty otherwise; throws Error(kExitUsage) with the message
// runCommandLine would print.
std::string parseCommandOptions(const std::string& path, const std::string& description,
                                const std::function<void(CLI::App*)>& addOptions,
                                const std::vector<std::string>& arguments);

// Options. Counts, numbers and choices show their default (the variable's value when declared) and their range in
// the help; text shows its default when asked to.
void addFlag(CLI::App* command, const std::string& name, bool& value, const std::string& help);
void addText(CLI::App* command, const std::string& name, std::string& value, const std::string& metavar,
             const std::string& help, bool showDefault = false);
// An option that may be given many times, each value kept in order.
void addTextList(CLI::App* command, const std::string& name, std::vector<std::string>& values,
                 const std::string& metavar, const std::string& help);
void addCount(CLI::App* command, const std::string& name, std::uint32_t& value, const std::string& help,
              std::uint32_t min, std::uint32_t max);
void addOptionalCount(CLI::App* command, const std::string& name, std::optional<std::uint32_t>& value,
                      const std::string& help, std::uint32_t min, std::uint32_t max);
void addNumber(CLI::App* command, const std::string& name, float& value, const std::string& help, float min,
               float max);
void addOptionalNumber(CLI::App* command, const std::string& name, std::optional<float>& value,
                       const std::string& help, float min, float max);
void addChoice(CLI::App* command, const std::string& name, std::string& value, const std::vector<std::string>& choices,
               const std::string& help);
void addPositional(CLI::App* command, const std::string& name, std::string& value, const std::string& help);

// The names options take, as the kernels and images use them.
ToneMap parseToneMap(const std::string& name);
// Throws Error(kExitUsage) "<command>: <option>: 'path' must end in <extension>".
void requireExtension(const std::string& command, const std::string& option, const std::string& path,
                      const std::string& extension);

// The groups several commands share.
// SCENE (positional), --camera, --allow-outside-uris, --env, --env-strength, --env-rotation.
void addSceneOptions(CLI::App* command, SceneRequest& request);
// --integrator auto|slides|path.
// A render option of util/render_options.h: its name, values, help and default (set into `value`).
void addChoiceOption(CLI::App* command, const ChoiceOption& option, std::string& value);
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
