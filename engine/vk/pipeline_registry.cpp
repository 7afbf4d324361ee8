#include "vk/pipeline_registry.h"

#include <algorithm>

namespace lagoon::vk {

void PipelineRegistry::add(const std::shared_ptr<PipelineRecipe>& recipe) {
  std::lock_guard lock(mutex_);
  // Renderers come and go in one context (tests, the demo's model switch): the dead ones' entries go.
  if (recipes_.size() >= 64 && recipes_.size() == recipes_.capacity())
    std::erase_if(recipes_, [](const std::weak_ptr<PipelineRecipe>& r) { return r.expired(); });
  recipes_.push_back(recipe);
}

void PipelineRegistry::used(const std::string& key) {
  std::lock_guard lock(mutex_);
  used_.push_back(key);
}

std::vector<std::string> PipelineRegistry::used_keys(size_t from) const {
  std::lock_guard lock(mutex_);
  return {used_.begin() + long(std::min(from, used_.size())), used_.end()};
}

size_t PipelineRegistry::used_count() const {
  std::lock_guard lock(mutex_);
  return used_.size();
}

std::vector<std::shared_ptr<PipelineRecipe>> PipelineRegistry::find(std::span<const std::string> keys) const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<PipelineRecipe>> out;
  for (const std::string& key : keys)
    for (const std::weak_ptr<PipelineRecipe>& weak : recipes_)
      if (std::shared_ptr<PipelineRecipe> r = weak.lock(); r && r->key == key) out.push_back(std::move(r));
  return out;
}

}  // namespace lagoon::vk
