#pragma once

namespace raylab {

// Mesa's on-disk shader cache keys a lavapipe kernel by its SPIR-V and the driver build, not by the environment
// settings that change the machine code: LP_NATIVE_VECTOR_WIDTH (the subgroup size) and GALLIVM_PERF (LLVM's passes).
// A kernel compiled for 8 lanes and loaded by a driver running 4 corrupts the heap (measured: `raylab view` aborted
// with "corrupted size vs. prev_size" after a run with the driver's defaults had filled the cache), and a kernel
// compiled without optimisation, loaded by an optimised run, runs that run's renders unoptimised. So where either is
// set, raylab points Mesa at a cache of their own,
// <cache>/raylab-lavapipe-width<W>-perf<P>, before the driver is loaded; with neither set, Mesa's own cache is
// untouched. Called by createInstance.
void separateShaderCacheByDriverSettings();

}  // namespace raylab
