// raylab: one executable, one command per job (cli.h: the command line on CLI11).
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "cli.h"
#include "commands.h"
#include "util/error.h"
#include "vk/device.h"

namespace {

// One prefix per message: "raylab render: ...". Messages that already name their command keep their own.
void printError(const std::string& command, const std::string& message) {
  if (message.rfind("raylab ", 0) == 0) {
    std::fprintf(stderr, "%s\n", message.c_str());
  } else {
    std::fprintf(stderr, "%s: %s\n", command.c_str(), message.c_str());
  }
}

// "raylab render": the command that failed, for its error message.
std::string commandPath(const CLI::App& app) {
  std::string path;
  raylab::deepestCommand(app, path);
  return path;
}

}  // namespace

int main(int argc, char** argv) {
  const std::unique_ptr<CLI::App> app = raylab::makeCommandLine();
  raylab::addRenderCommand(*app);
  raylab::addSweepCommand(*app);
  raylab::addViewCommand(*app);
  raylab::addBrdfCommands(*app);
  raylab::addBenchCommands(*app);
  raylab::addDevicesCommand(*app);

  int code = raylab::kExitFailure;
  try {
    code = raylab::runCommandLine(*app, argc, argv);
  } catch (const raylab::Error& error) {
    printError(commandPath(*app), error.what());
    code = error.exitCode();
  } catch (const std::bad_alloc&) {
    printError(commandPath(*app),
               "out of memory (the input asks for more than this machine has; see the limits in docs/scenes.md)");
    code = raylab::kExitFailure;
  } catch (const std::exception& error) {
    printError(commandPath(*app), std::string("unexpected error: ") + error.what());
    code = raylab::kExitFailure;
  }
  // With validation on, any message is a bug: make it impossible to miss.
  if (const std::uint32_t messages = raylab::validationMessageCount(); messages > 0) {
    std::fprintf(stderr, "raylab: %u Vulkan validation message(s), see above\n", messages);
    if (code == raylab::kExitOk) code = raylab::kExitFailure;
  }
  return code;
}
