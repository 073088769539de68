// The benchmarks behind `raylab bench <name>`; each parses its own arguments.
#pragma once

namespace raylab {

int benchKernels(int argc, char** argv);
int benchOrder(int argc, char** argv);
int benchRays(int argc, char** argv);
int benchView(int argc, char** argv);

}  // namespace raylab
