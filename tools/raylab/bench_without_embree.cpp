// `raylab bench rays|order` in a build without Embree (-DRAYLAB_EMBREE=OFF): they measure raylab against it,
// so they say so and exit 2.
#include <string>

#include "bench_commands.h"
#include "command_line/cli.h"
#include "util/error.h"

namespace raylab {

namespace {

void addWithoutEmbree(CLI::App& bench, const std::string& name) {
  addCommand(bench, name, "(not in this build: it measures raylab against Embree 3)", [name]() -> int {
    throw Error("raylab bench " + name +
                    " measures raylab against Embree 3, and this raylab was built without it (-DRAYLAB_EMBREE=OFF); "
                    "configure with -DRAYLAB_EMBREE=ON (Debian libembree-dev)",
                kExitUsage);
  });
}

}  // namespace

void addBenchRaysCommand(CLI::App& bench) { addWithoutEmbree(bench, "rays"); }
void addBenchOrderCommand(CLI::App& bench) { addWithoutEmbree(bench, "order"); }

}  // namespace raylab
