// What a device keeps of the kernels it has built, so that building one again costs nothing.
//
// On lavapipe, creating a pipeline translates and optimises its SPIR-V every time (0.2-2 s for a render kernel);
// Mesa's disk cache keeps only the LLVM code of the first dispatch, and a VkPipelineCache does not skip the
// translation either (measured: a second creation in the same process takes as long as the first). Renderers are
// made and unmade often with the same kernel: a test's many renders of one scene, the Python module's Renderer per
// call and the farm's jobs in one worker. So the device keeps each pipeline it built, by what determines it (the
// kernel's entry points and specialisation constants, and its layout), and hands the same one out again, compiled
// already by its first dispatch.
//
// Layouts are kept for the device's life, one per distinct description: they are few and small, and a stable
// layout handle is what lets a pipeline be found again by it. Pipelines are counted: a released one nobody uses is
// kept among the last kKeptUnused such, the oldest beyond that destroyed. destroyDevice destroys all of it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace raylab {

class PipelineStore {
 public:
  static constexpr std::size_t kKeptUnused = 8;

  // The layout stored under `key`, made by `create` the first time. Thread-safe.
  VkDescriptorSetLayout setLayout(const std::string& key, const std::function<VkDescriptorSetLayout()>& create);
  VkPipelineLayout pipelineLayout(const std::string& key, const std::function<VkPipelineLayout()>& create);

  // The pipeline stored under (`layout`, `key`), counted as used once more, or made by `create` (outside the lock:
  // another thread may build another kernel meanwhile) and stored. Thread-safe.
  VkPipeline acquire(VkDevice device, VkPipelineLayout layout, const std::string& key,
                     const std::function<VkPipeline()>& create);
  // One use of `pipeline` ends; VK_NULL_HANDLE is ignored. The device must no longer be running it if it ends the
  // last use (as for vkDestroyPipeline). A pipeline the store does not hold is destroyed.
  void release(VkDevice device, VkPipeline pipeline);

  std::size_t storedPipelines() const;
  void destroyAll(VkDevice device);

 private:
  struct Entry {
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::uint32_t users = 0;
    std::uint64_t lastReleased = 0;  // release order: the oldest unused go first
  };
  void evictUnused(VkDevice device);  // with the lock held

  mutable std::mutex mutex_;
  std::map<std::string, VkDescriptorSetLayout> setLayouts_;
  std::map<std::string, VkPipelineLayout> pipelineLayouts_;
  std::map<std::string, Entry> pipelines_;
  std::uint64_t releases_ = 0;
};

}  // namespace raylab
