// raylab: one executable, one subcommand per job.
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "commands.h"
#include "util/error.h"
#include "vk/device.h"

namespace {

struct Command {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

constexpr Command kCommands[] = {
    {"render", raylab::runRender, "render a scene offscreen to OpenEXR and PNG"},
    {"sweep", raylab::runSweep, "render a parameter sweep of one BRDF model into a labelled contact sheet"},
    {"view", raylab::runView, "open an interactive window on a scene (X11; headless: xvfb-run -a)"},
    {"brdf", raylab::runBrdf, "the BRDF library outside the renderer (brdf eval, brdf albedo)"},
    {"bench", raylab::runBench, "benchmarks: kernel variants, ray throughput against Embree, the viewer"},
    {"devices", raylab::runDevices, "list Vulkan devices and whether raylab can use them"},
};

void printUsage(std::FILE* stream) {
  std::fprintf(stream,
               "Usage: raylab <command> [options]\n\n"
               "raylab is an interactive ray tracer built around a library of analytic BRDFs, running on any\n"
               "Vulkan 1.2 device with ray queries (Mesa's lavapipe included).\n\nCommands:\n");
  for (const Command& command : kCommands) std::fprintf(stream, "  %-10s %s\n", command.name, command.summary);
  std::fprintf(stream,
               "\n`raylab <command> --help` describes each command.\n"
               "Environment: RAYLAB_VALIDATION=1 enables the Vulkan validation layers.\n");
}

// One prefix per message: "raylab render: ...". Messages that already name their command keep their own.
void printError(const char* command, const std::string& message) {
  if (message.rfind("raylab ", 0) == 0) {
    std::fprintf(stderr, "%s\n", message.c_str());
  } else {
    std::fprintf(stderr, "raylab %s: %s\n", command, message.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    printUsage(stderr);
    return raylab::kExitUsage;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    printUsage(stdout);
    return raylab::kExitOk;
  }
  if (name == "--version") {
    std::printf("raylab " RAYLAB_VERSION "\n");
    return raylab::kExitOk;
  }
  for (const Command& command : kCommands) {
    if (name != command.name) continue;
    int code = raylab::kExitFailure;
    try {
      code = command.run(argc - 2, argv + 2);
    } catch (const raylab::Error& error) {
      printError(command.name, error.what());
      code = error.exitCode();
    } catch (const std::bad_alloc&) {
      printError(command.name, "out of memory (the input asks for more than this machine has; see the limits in "
                               "docs/scenes.md)");
      code = raylab::kExitFailure;
    } catch (const std::exception& error) {
      printError(command.name, std::string("unexpected error: ") + error.what());
      code = raylab::kExitFailure;
    }
    // With validation on, any message is a bug: make it impossible to miss.
    if (const std::uint32_t messages = raylab::validationMessageCount(); messages > 0) {
      std::fprintf(stderr, "raylab: %u Vulkan validation message(s), see above\n", messages);
      if (code == raylab::kExitOk) code = raylab::kExitFailure;
    }
    return code;
  }
  std::fprintf(stderr, "raylab: unknown command '%s'\n\n", name.c_str());
  printUsage(stderr);
  return raylab::kExitUsage;
}
