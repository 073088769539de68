#include "vk/pipeline_store.h"

#include <algorithm>
#include <vector>

namespace raylab {

namespace {

template <typename Handle>
Handle findOrCreate(std::mutex& mutex, std::map<std::string, Handle>& stored, const std::string& key,
                    const std::function<Handle()>& create) {
  // Under the lock throughout: layouts take microseconds, and two threads must not both create one.
  const std::lock_guard lock(mutex);
  if (const auto found = stored.find(key); found != stored.end()) return found->second;
  const Handle handle = create();
  stored.emplace(key, handle);
  return handle;
}

std::string pipelineKey(VkPipelineLayout layout, const std::string& key) {
  return std::to_string(reinterpret_cast<std::uintptr_t>(layout)) + "|" + key;
}

}  // namespace

VkDescriptorSetLayout PipelineStore::setLayout(const std::string& key,
                                               const std::function<VkDescriptorSetLayout()>& create) {
  return findOrCreate(mutex_, setLayouts_, key, create);
}

VkPipelineLayout PipelineStore::pipelineLayout(const std::string& key, const std::function<VkPipelineLayout()>& create) {
  return findOrCreate(mutex_, pipelineLayouts_, key, create);
}

VkPipeline PipelineStore::acquire(VkDevice device, VkPipelineLayout layout, const std::string& key,
                                  const std::function<VkPipeline()>& create) {
  const std::string fullKey = pipelineKey(layout, key);
  {
    const std::lock_guard lock(mutex_);
    if (const auto found = pipelines_.find(fullKey); found != pipelines_.end()) {
      ++found->second.users;
      return found->second.pipeline;
    }
  }
  const VkPipeline created = create();
  const std::lock_guard lock(mutex_);
  const auto [entry, inserted] = pipelines_.try_emplace(fullKey, Entry{created, 0, 0});
  if (!inserted) vkDestroyPipeline(device, created, nullptr);  // another thread built the same one meanwhile
  ++entry->second.users;
  return entry->second.pipeline;
}

void PipelineStore::release(VkDevice device, VkPipeline pipeline) {
  if (pipeline == VK_NULL_HANDLE) return;
  const std::lock_guard lock(mutex_);
  const auto entry = std::find_if(pipelines_.begin(), pipelines_.end(),
                                  [&](const auto& stored) { return stored.second.pipeline == pipeline; });
  if (entry == pipelines_.end()) {
    vkDestroyPipeline(device, pipeline, nullptr);
    return;
  }
  if (entry->second.users > 0 && --entry->second.users == 0) entry->second.lastReleased = ++releases_;
  evictUnused(device);
}

void PipelineStore::evictUnused(VkDevice device) {
  std::vector<std::map<std::string, Entry>::iterator> unused;
  for (auto it = pipelines_.begin(); it != pipelines_.end(); ++it) {
    if (it->second.users == 0) unused.push_back(it);
  }
  if (unused.size() <= kKeptUnused) return;
  std::sort(unused.begin(), unused.end(),
            [](const auto& a, const auto& b) { return a->second.lastReleased < b->second.lastReleased; });
  for (std::size_t i = 0; i + kKeptUnused < unused.size(); ++i) {
    vkDestroyPipeline(device, unused[i]->second.pipeline, nullptr);
    pipelines_.erase(unused[i]);
  }
}

std::size_t PipelineStore::storedPipelines() const {
  const std::lock_guard lock(mutex_);
  return pipelines_.size();
}

void PipelineStore::destroyAll(VkDevice device) {
  const std::lock_guard lock(mutex_);
  for (const auto& [key, entry] : pipelines_) vkDestroyPipeline(device, entry.pipeline, nullptr);
  for (const auto& [key, layout] : pipelineLayouts_) vkDestroyPipelineLayout(device, layout, nullptr);
  for (const auto& [key, layout] : setLayouts_) vkDestroyDescriptorSetLayout(device, layout, nullptr);
  pipelines_.clear();
  pipelineLayouts_.clear();
  setLayouts_.clear();
}

}  // namespace raylab
