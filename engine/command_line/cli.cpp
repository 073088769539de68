#include "command_line/cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "render/renderer.h"
#include "util/error.h"

namespace raylab {

namespace {

constexpr std::size_t kHelpWidth = 100;
constexpr std::size_t kOptionColumn = 30;

// Greedy word wrap of `text` into lines of at most `width` characters after `indent` spaces (the first line's
// indent is the caller's).
std::string wrap(const std::string& text, std::size_t indent, std::size_t width) {
  std::string out, line;
  std::istringstream paragraphs(text);
  std::string paragraph;
  bool firstParagraph = true;
  while (std::getline(paragraphs, paragraph)) {
    if (!firstParagraph) out += "\n" + std::string(indent, ' ');
    firstParagraph = false;
    std::istringstream words(paragraph);
    std::string word;
    line.clear();
    while (words >> word) {
      if (!line.empty() && line.size() + 1 + word.size() > width - indent) {
        out += line + "\n" + std::string(indent, ' ');
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    out += line;
  }
  return out;
}

// CLI11's formatter with descriptions wrapped to the terminal's usual width, and the option column fixed.
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter() { column_width(kOptionColumn); }

  // Usage first, as most tools print it; then the description, arguments, options and commands.
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return CLI::Formatter::make_help(app, name, mode);
    std::string out = make_usage(app, name) + "\n" + make_description(app) + make_positionals(app) +
                      make_groups(app, mode) + make_subcommands(app, mode);
    const std::string footer = make_footer(app);
    return footer.empty() ? out : out + "\n" + footer;
  }

  // The summary line, then the rest of the description as its own paragraph.
  std::string make_description(const CLI::App* app) const override {
    const std::string description = app->get_description();
    if (description.empty()) return {};
    const std::size_t newline = description.find('\n');
    if (newline == std::string::npos) return wrap(description, 0, kHelpWidth) + "\n";
    return wrap(description.substr(0, newline), 0, kHelpWidth) + "\n\n" +
           wrap(description.substr(newline + 1), 0, kHelpWidth) + "\n";
  }

  // In a list of commands, only the first line of each one's description: the rest is its own help's.
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string description = sub->get_description();
    const std::string first = description.substr(0, description.find('\n'));
    std::string left = "  " + sub->get_name();
    left += std::string(left.size() + 1 < kOptionColumn ? kOptionColumn - left.size() : 1, ' ');
    return left + wrap(first, kOptionColumn, kHelpWidth) + "\n";
  }

  std::string make_option(const CLI::Option* option, bool positional) const override {
    std::string left = "  " + make_option_name(option, positional) + make_option_opts(option);
    std::string description = make_option_desc(option);
    std::string out = left;
    if (left.size() + 1 >= kOptionColumn) {
      out += "\n" + std::string(kOptionColumn, ' ');
    } else {
      out += std::string(kOptionColumn - left.size(), ' ');
    }
    return out + wrap(description, kOptionColumn, kHelpWidth) + "\n";
  }
};

// A finite number in [min, max]: CLI::Range alone lets NaN through.
CLI::Validator finiteRange(float min, float max) {
  char range[64];
  std::snprintf(range, sizeof range, "[%g, %g]", double(min), double(max));
  return CLI::Validator(
      [min, max, text = std::string(range)](std::string& input) -> std::string {
        char* end = nullptr;
        const float value = std::strtof(input.c_str(), &end);
        if (input.empty() || *end != '\0' || !std::isfinite(value)) return "expected a finite number, got '" + input + "'";
        if (value < min || value > max) return input + " is outside " + text;
        return {};
      },
      range);
}

// A whole number in [min, max], refusing signs and fractions (CLI::Range alone accepts what strtoul wraps).
// A text option given as '' (an empty --env, --compare, --out): refused, since it would otherwise silently mean
// the option's default.
CLI::Validator nonEmpty() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        return input.empty() ? "is empty (leave the option out for its default)" : std::string();
      },
      "");
}

CLI::Validator countRange(std::uint32_t min, std::uint32_t max) {
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& input) -> std::string {
        if (input.empty() || input.find_first_not_of("0123456789") != std::string::npos) {
          return "expected a whole number, got '" + input + "'";
        }
        if (input.size() > 10 || std::stoull(input) < min || std::stoull(input) > max) {
          return input + " is outside " + range;
        }
        return {};
      },
      range);
}

struct Command {
  CLI::App* app;
  std::function<int()> run;
};

std::vector<Command>& commands() {
  static std::vector<Command> all;
  return all;
}

// The deepest command given on the command line, and its path ("raylab brdf eval").
const CLI::App* deepestCommand(const CLI::App& app, std::string& path) {
  path = app.get_name();
  const CLI::App* current = &app;
  while (true) {
    const std::vector<const CLI::App*> given = current->get_subcommands([](const CLI::App* a) { return a->parsed(); });
    if (given.empty()) return current;
    current = given.front();
    path += " " + current->get_name();
  }
}

std::string commandNames(const CLI::App& app) {
  std::string names;
  const std::vector<const CLI::App*> all = app.get_subcommands([](const CLI::App*) { return true; });
  for (std::size_t i = 0; i < all.size(); ++i) {
    names += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i]->get_name();
  }
  return names;
}

std::unique_ptr<CLI::App> makeRoot() {
  auto app = std::make_unique<CLI::App>(
      "raylab is an interactive ray tracer built around a library of analytic BRDFs, running on any Vulkan 1.2 "
      "device with ray queries or ray-tracing pipelines (Mesa's lavapipe included).",
      "raylab");
  app->formatter(std::make_shared<HelpFormatter>());
  app->require_subcommand(1);
  app->set_version_flag("--version", "raylab " RAYLAB_VERSION);
  app->footer("`raylab <command> --help` describes each command.\n"
              "Environment: RAYLAB_VALIDATION=1 enables the Vulkan validation layers.");
  return app;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// " (did you mean --spp?)" for the first word of `words` that looks like an option `command` does not have and is
// close to one it has (two edits, or a third of its letters when longer); empty otherwise.
std::string didYouMean(const CLI::App& command, const std::vector<std::string>& words) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  for (std::string word : words) {
    if (word.rfind("--", 0) != 0) continue;
    word = word.substr(0, word.find('='));
    if (std::find(names.begin(), names.end(), word) != names.end()) continue;
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(2, (word.size() - 2) / 3) + 1;  // up to 2 edits, more if long
    for (const std::string& name : names) {
      const std::size_t distance = editDistance(word, name);
      if (distance < bestDistance) best = name, bestDistance = distance;
    }
    return best.empty() ? "" : " (did you mean " + best + "?)";
  }
  return "";
}

// One prefix per message: "raylab render: ...". Messages that already name their command keep their own.
void printError(const std::string& command, const std::string& message) {
  if (message.rfind("raylab ", 0) == 0) {
    std::fprintf(stderr, "%s\n", message.c_str());
  } else {
    std::fprintf(stderr, "%s: %s\n", command.c_str(), message.c_str());
  }
}

int parseAndRun(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return kExitOk;
  } catch (const CLI::CallForVersion& version) {
    std::printf("%s\n", version.what());
    return kExitOk;
  } catch (const CLI::ParseError& error) {
    std::string path;
    const CLI::App* command = deepestCommand(app, path);
    if (command == &app && argc < 2) {
      std::fputs(app.help().c_str(), stderr);
      return kExitUsage;
    }
    std::string message = error.what();
    // A group given without one of its commands, or a word that is no command: say which exist.
    if (command->get_require_subcommand_min() > 0 && command->get_subcommands().empty()) {
      const char* kind = command == &app ? "command" : "subcommand";
      const int next = 1 + int(std::count(path.begin(), path.end(), ' '));
      if (next < argc && argv[next][0] != '-') {
        message = std::string("unknown ") + kind + " '" + argv[next] + "'; the " + kind + "s are " +
                  commandNames(*command);
      } else {
        // A group alone: its help says what it holds.
        std::fprintf(stderr, "%s: which %s? (%s)\n\n%s", path.c_str(), kind, commandNames(*command).c_str(),
                     app.help().c_str());
        return kExitUsage;
      }
    }
    message += didYouMean(*command, std::vector<std::string>(argv + 1, argv + argc));
    std::fprintf(stderr, "%s: %s (see `%s --help`)\n", path.c_str(), message.c_str(), path.c_str());
    return kExitUsage;
  }
  for (const Command& command : commands()) {
    if (command.app->parsed()) return command.run();
  }
  return kExitOk;
}

}  // namespace

std::string parseCommandOptions(const std::string& path, const std::string& description,
                                const std::function<void(CLI::App*)>& addOptions,
                                const std::vector<std::string>& arguments) {
  CLI::App app(description, path);
  app.formatter(std::make_shared<HelpFormatter>());
  addOptions(&app);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    return app.help();
  } catch (const CLI::ParseError& error) {
    throw Error(path + ": " + error.what() + didYouMean(app, arguments) + " (see `" + path + " --help`)", kExitUsage);
  }
  return "";
}

CLI::App* addCommand(CLI::App& parent, const std::string& name, const std::string& description,
                     std::function<int()> run) {
  CLI::App* command = parent.add_subcommand(name, description);
  command->footer("");  // the root's footer is about the list of commands
  commands().push_back({command, std::move(run)});
  return command;
}

CLI::App* addCommandGroup(CLI::App& parent, const std::string& name, const std::string& description) {
  CLI::App* group = parent.add_subcommand(name, description);
  group->require_subcommand(1);
  group->footer("`" + parent.get_name() + " " + name + " <command> --help` describes each command.");
  return group;
}

int runCommandLine(int argc, char** argv, const std::function<void(CLI::App&)>& addCommands) {
  const std::unique_ptr<CLI::App> app = makeRoot();
  addCommands(*app);
  std::string path;
  try {
    return parseAndRun(*app, argc, argv);
  } catch (const Error& error) {
    deepestCommand(*app, path);
    printError(path, error.what());
    return error.exitCode();
  } catch (const std::bad_alloc&) {
    deepestCommand(*app, path);
    printError(path, "out of memory (the input asks for more than this machine has; see the limits in docs/scenes.md)");
    return kExitFailure;
  } catch (const std::exception& error) {
    deepestCommand(*app, path);
    printError(path, std::string("unexpected error: ") + error.what());
    return kExitFailure;
  }
}

ToneMap parseToneMap(const std::string& name) {
  if (name == "aces") return ToneMap::kAces;
  if (name == "reinhard") return ToneMap::kReinhard;
  return ToneMap::kClamp;
}

void requireExtension(const std::string& command, const std::string& option, const std::string& path,
                      const std::string& extension) {
  if (std::filesystem::path(path).extension() != extension) {
    throw Error(command + ": " + option + ": '" + path + "' must end in " + extension, kExitUsage);
  }
}

void addFlag(CLI::App* command, const std::string& name, bool& value, const std::string& help) {
  command->add_flag(name, value, help);
}

void addText(CLI::App* command, const std::string& name, std::string& value, const std::string& metavar,
             const std::string& help, bool showDefault) {
  CLI::Option* option = command->add_option(name, value, help)->type_name(metavar)->check(nonEmpty());
  if (showDefault) option->capture_default_str();
}

void addTextList(CLI::App* command, const std::string& name, std::vector<std::string>& values,
                 const std::string& metavar, const std::string& help) {
  command->add_option(name, values, help)->type_name(metavar)->check(nonEmpty());
}

void addCount(CLI::App* command, const std::string& name, std::uint32_t& value, const std::string& help,
              std::uint32_t min, std::uint32_t max) {
  command->add_option(name, value, help)->check(countRange(min, max))->type_name("N")->capture_default_str();
}

void addOptionalCount(CLI::App* command, const std::string& name, std::optional<std::uint32_t>& value,
                      const std::string& help, std::uint32_t min, std::uint32_t max) {
  command->add_option_function<std::uint32_t>(name, [&value](const std::uint32_t& parsed) { value = parsed; }, help)
      ->check(countRange(min, max))
      ->type_name("N");
}

void addNumber(CLI::App* command, const std::string& name, float& value, const std::string& help, float min,
               float max) {
  command->add_option(name, value, help)->check(finiteRange(min, max))->type_name("X")->capture_default_str();
}

void addOptionalNumber(CLI::App* command, const std::string& name, std::optional<float>& value,
                       const std::string& help, float min, float max) {
  command->add_option_function<float>(name, [&value](const float& parsed) { value = parsed; }, help)
      ->check(finiteRange(min, max))
      ->type_name("X");
}

void addChoice(CLI::App* command, const std::string& name, std::string& value, const std::vector<std::string>& choices,
               const std::string& help) {
  std::string names;
  for (const std::string& choice : choices) names += (names.empty() ? "" : "|") + choice;
  command->add_option(name, value, help)
      ->check(CLI::IsMember(choices).description(""))
      ->type_name(names)
      ->capture_default_str();
}

void addPositional(CLI::App* command, const std::string& name, std::string& value, const std::string& help) {
  command->add_option(name, value, help)->type_name("FILE")->check(nonEmpty());
}

void addDeviceOption(CLI::App* command, std::optional<std::uint32_t>& device) {
  addOptionalCount(command, "--device", device, "Vulkan device index from `raylab devices` (default: the best capable)",
                   0, 1000);
}

void addImageSizeOptions(CLI::App* command, std::uint32_t& width, std::uint32_t& height, const std::string& what,
                         std::uint32_t minSide) {
  addCount(command, "--width", width, what + " width in pixels", minSide, kMaxImageSide);
  addCount(command, "--height", height, what + " height in pixels", minSide, kMaxImageSide);
}

void addSceneOptions(CLI::App* command, SceneRequest& request) {
  addPositional(command, "SCENE", request.path, "a .gltf or .glb file (default: the built-in scene)");
  addText(command, "--camera", request.camera, "NAME", "the glTF camera (or its node) to use (default: the first)");
  addFlag(command, "--allow-outside-uris", request.allowOutsideUris,
          "let the scene's buffers and images lie outside its directory (only for files you trust)");
  addText(command, "--env", request.environment, "FILE.exr",
          "light the scene with this equirectangular HDR image (+Y up), replacing the scene's own");
  addOptionalNumber(command, "--env-strength", request.environmentStrength,
                    "multiplies the environment image (default: the scene's, or 1)", 0.0f, 1e30f);
  addOptionalNumber(command, "--env-rotation", request.environmentRotation,
                    "turns the environment image about +Y, degrees counter-clockwise seen from above (default: the "
                    "scene's, or 0)",
                    -kMaxEnvironmentRotationDegrees, kMaxEnvironmentRotationDegrees);
}

void addChoiceOption(CLI::App* command, const ChoiceOption& option, std::string& value) {
  value = std::string(option.defaultValue);
  addChoice(command, "--" + std::string(option.name), value,
            std::vector<std::string>(option.values.begin(), option.values.end()), std::string(option.help));
}

void addIntegratorOption(CLI::App* command, std::string& integrator) {
  addChoiceOption(command, kIntegratorOption, integrator);
}

void addSampleOptions(CLI::App* command, RenderSettings& settings) {
  addCount(command, "--seed", settings.seed, "random seed of the sample pattern", 0, UINT32_MAX);
  addCount(command, "--" + std::string(kMaxDepthOption.name), settings.maxDepth, std::string(kMaxDepthOption.help),
           kMaxDepthOption.min, kMaxDepthOption.max);
}

void addToneOptions(CLI::App* command, float& exposure, std::string& toneMap, const std::string& what) {
  addNumber(command, "--exposure", exposure, "exposure of " + what + " in stops", -kMaxExposureStops, kMaxExposureStops);
  addChoice(command, "--tonemap", toneMap, {"clamp", "reinhard", "aces"}, "tone curve of " + what);
}

void addBackendOption(CLI::App* command, std::string& backend) { addChoiceOption(command, kBackendOption, backend); }

void addBenchBackendOption(CLI::App* command, std::string& backend) {
  addChoice(command, "--backend", backend, {"all", "auto", "query", "pipeline"},
            "all: every backend the device offers, side by side; or only auto, query or pipeline");
}

}  // namespace raylab
