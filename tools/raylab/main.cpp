// raylab: one executable, one command per job (cli.h: the command line on CLI11).
#include <cstdio>

#include "command_line/cli.h"
#include "commands.h"
#include "util/error.h"
#include "vk/device.h"

int main(int argc, char** argv) {
  int code = raylab::runCommandLine(argc, argv, [](CLI::App& raylab) {
    raylab::addRenderCommand(raylab);
    raylab::addSweepCommand(raylab);
    raylab::addViewCommand(raylab);
    raylab::addBrdfCommands(raylab);
    raylab::addBenchCommands(raylab);
    raylab::addInfoCommand(raylab);
    raylab::addDevicesCommand(raylab);
  });
  // With validation on, any message is a bug: make it impossible to miss.
  if (const std::uint32_t messages = raylab::validationMessageCount(); messages > 0) {
    std::fprintf(stderr, "raylab: %u Vulkan validation message(s), see above\n", messages);
    if (code == raylab::kExitOk) code = raylab::kExitFailure;
  }
  return code;
}
