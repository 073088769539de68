// Builds a render-kernel variant on a background thread while the viewer keeps drawing, for a material that
// switched to a BRDF model the current kernel was not specialised for.
//
// lavapipe compiles a pipeline with LLVM at its first dispatch, on the thread that executes the queue, not
// in vkCreateComputePipelines; on the viewer's one queue that would freeze the window for 1-3 s. So on a CPU
// device the thread also runs one tiny dispatch of the variant on a private VkDevice (its own queue and
// queue thread): Mesa's shader cache, shared by every device of the process, then holds the compiled code,
// and the viewer's first dispatch of the new pipeline finds it there. The viewer's own queue is touched by
// the main thread only. With MESA_SHADER_CACHE_DISABLE set the warm-up would be wasted and is skipped.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "render/renderer.h"
#include "vk/device.h"

namespace raylab {

struct KernelBuild {
  KernelFeatures kernel;
  std::thread thread;
  std::atomic<bool> finished{false};
  RenderPipelines pipelines;             // on the viewer's device, of the renderer's layout
  bool warmedUp = false;                 // the private-device warm-up ran
  double seconds = 0.0;
  std::string error;                     // set instead of pipeline when the build failed
};

// Starts building `kernel` for `renderer`'s pipeline layout.
std::unique_ptr<KernelBuild> startKernelBuild(const Instance& instance, const Device& device, const Renderer& renderer,
                                              const KernelFeatures& kernel);

// Waits for the thread (immediately when `finished`), hands over the pipelines; throws Error when the build failed.
RenderPipelines finishKernelBuild(const Device& device, KernelBuild& build);

// Waits for the thread and destroys whatever it built (shutdown, or a newer build replacing this one).
void abandonKernelBuild(const Device& device, KernelBuild& build);

}  // namespace raylab
