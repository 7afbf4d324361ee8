#include "vk/pipeline_recipe.h"

#include "vk/pipeline_registry.h"

namespace lagoon::vk {

VkPipeline PipelineRecipe::made_locked() {
  if (make) {
    pipeline = Unique<VkPipeline>(device, make());
    make = nullptr;  // frees what the recipe captured
  }
  return pipeline;
}

VkPipeline PipelineRecipe::made() {
  std::lock_guard lock(mutex);
  return made_locked();
}

VkPipeline PipelineRecipe::use() {
  std::lock_guard lock(mutex);
  const VkPipeline p = made_locked();
  if (!used && registry) registry->used(key);
  used = true;
  return p;
}

}  // namespace lagoon::vk
