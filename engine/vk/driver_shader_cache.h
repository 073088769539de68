#pragma once

namespace raylab {

// Mesa's on-disk shader cache keys a lavapipe kernel by its SPIR-V and the driver build, not by the environment
// settings that change the machine code. One of them changes what the code assumes: LP_NATIVE_VECTOR_WIDTH, the
// subgroup size. A kernel compiled for 8 lanes and loaded by a driver running 4 corrupts the heap (measured: `raylab
// view` aborted with "corrupted size vs. prev_size" after a run with the driver's defaults had filled the cache). So
// where it is set, raylab points Mesa at a cache of its own, <cache>/raylab-lavapipe-width<W>, before the driver is
// loaded; unset, Mesa's own cache is untouched. GALLIVM_PERF (LLVM's passes) only changes how fast the same
// computation runs, so kernels compiled with and without optimisation share a cache, as the tests rely on
// (docs/architecture.md, "How long the suite takes"). Called by createInstance.
void separateShaderCacheByVectorWidth();

}  // namespace raylab
