// `raylab bench rays|order` in a build without Embree (-DRAYLAB_EMBREE=OFF): they measure raylab against it.
#include "bench_commands.h"
#include "util/error.h"

namespace raylab {

namespace {

[[noreturn]] void withoutEmbree(const char* benchmark) {
  throw Error(std::string("raylab bench ") + benchmark +
                  " measures raylab against Embree 3, and this raylab was built without it (-DRAYLAB_EMBREE=OFF); "
                  "configure with -DRAYLAB_EMBREE=ON (Debian libembree-dev)",
              kExitUsage);
}

}  // namespace

int benchRays(int, char**) { withoutEmbree("rays"); }
int benchOrder(int, char**) { withoutEmbree("order"); }

}  // namespace raylab
