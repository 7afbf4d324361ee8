#include "vk/pipeline_recipe.h"

#include "vk/pipeline_registry.h"

namespace lagoon::vk {

VkPipeline PipelineRecipe::made() {
  std::lock_guard lock(mutex);
  if (make) {
    pipeline = Unique<VkPipeline>(device, make());
    make = nullptr;  // frees what the recipe captured
  }
  return pipeline;
}

VkPipeline PipelineRecipe::use() {
  const VkPipeline p = made();
  std::lock_guard lock(mutex);
  if (!used && registry) registry->used(key);
  used = true;
  return p;
}

}  // namespace lagoon::vk
