// Kernel rebuilds: a material switched to a model, a light to a kind, or a feature turned on, that the specialised kernel lacks
// starts a background build (kernel_build.h), which is installed when it lands.
#include "view/viewer_state.h"

#include <cstdio>

#include "util/error.h"

namespace raylab {

bool covers(const KernelFeatures& kernel, const KernelFeatures& needed) {
  return (needed.models & ~kernel.models) == 0 && (needed.features & ~kernel.features) == 0 &&
         (needed.lightKinds & ~kernel.lightKinds) == 0 && needed.integrator == kernel.integrator;
}

void installKernel(Viewer& v) {
  RenderPipelines pipelines;
  try {
    pipelines = finishKernelBuild(v.device, *v.build);
  } catch (const Error& error) {
    v.build.reset();
    if (v.automation) throw;
    v.status.message = error.what();
    return;
  }
  waitForFrames(v);  // the old pipeline may still be running
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f s", v.build->seconds);
  const std::string message = std::string("kernel rebuilt in ") + seconds +
                              (v.build->warmedUp ? " (compiled off-queue)" : "") + ": " + describe(v.build->kernel);
  swapRenderPipelines(v.device, v.renderer, pipelines, v.build->kernel);
  v.status.message = message;
  if (!v.options.quiet) std::printf("raylab view: %s\n", message.c_str());
  v.build.reset();
  v.kernelState = KernelState::kFirstDispatch;
  v.pending.accumulation = true;
}

// Starts a background build when the scene needs models or features the kernel lacks. Until it is swapped in
// the viewer traces nothing and keeps showing the last image.
void ensureKernel(Viewer& v) {
  if (covers(v.renderer.kernel, v.needed) || v.build) return;  // a running build is re-checked when it lands
  KernelFeatures wanted = v.needed;
  wanted.models |= v.renderer.kernel.models;
  wanted.features |= v.renderer.kernel.features;
  wanted.lightKinds |= v.renderer.kernel.lightKinds;
  v.build = startKernelBuild(v.instance, v.device, v.renderer, wanted);
  if (v.automation) installKernel(v);  // automation is deterministic: the frame waits for its kernel
}

// The integrator of v.settings: a kernel of its own, built in the background like a new model's.
void switchIntegrator(Viewer& v) {
  if (v.integrator == v.settings.integrator) return;
  v.integrator = v.settings.integrator;
  v.needed = neededKernel(v);
  ensureKernel(v);
  refreshComparison(v);
  v.pending.accumulation = true;
}

}  // namespace raylab
