// The pipelines a context's users have declared (vk::ComputePipeline, vk::GraphicsPipeline), by key, and the
// keys of those used so far in the order they were first used: a renderer remembers the part of that list
// its own frames used and has the next run make them ahead, on another thread (vk/pipeline_warmer.h). On
// lavapipe making a pipeline is tens of milliseconds of the CPU even when Mesa's shader cache holds its code
// (~300 ms of a warm still frame of the bay).
#pragma once
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "vk/pipeline_recipe.h"

namespace lagoon::vk {

class PipelineRegistry {
 public:
  void add(const std::shared_ptr<PipelineRecipe>& recipe);
  // Called by a recipe at its first use.
  void used(const std::string& key);
  // The keys of the pipelines used so far, in the order of their first use, from the `from`th on (another
  // pipeline with the same recipe appears again).
  std::vector<std::string> used_keys(size_t from = 0) const;
  size_t used_count() const;
  // The recipes still alive whose key is one of `keys` (made or not), in the order of `keys`.
  std::vector<std::shared_ptr<PipelineRecipe>> find(std::span<const std::string> keys) const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::weak_ptr<PipelineRecipe>> recipes_;
  std::vector<std::string> used_;
};

}  // namespace lagoon::vk
