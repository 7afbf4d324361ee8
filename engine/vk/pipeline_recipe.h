// How a pipeline is made, kept until it is (vk::DeferredPipeline holds one): shared with the context's
// registry (vk/pipeline_registry.h), so that another thread may make it ahead of its first use
// (vk/pipeline_warmer.h). The key names everything it is made from (its shaders, their specialisation and
// the fixed-function state), so two recipes with one key make the same pipeline, in this run or another.
#pragma once
#include <vulkan/vulkan.h>

#include <functional>
#include <mutex>
#include <string>

#include "vk/handle.h"

namespace lagoon::vk {

class PipelineRegistry;

struct PipelineRecipe {
  std::mutex mutex;
  VkDevice device = VK_NULL_HANDLE;
  std::string key;
  std::function<VkPipeline()> make;  // null once made, or once its owner is gone
  Unique<VkPipeline> pipeline;
  PipelineRegistry* registry = nullptr;  // told when it is first used; may be null
  bool used = false;

  // The pipeline, made here (under the lock) unless made already; VK_NULL_HANDLE when its owner is gone.
  VkPipeline made();
  // made(), for recording with it: the registry learns of its first use (a making ahead is not a use).
  VkPipeline use();

 private:
  VkPipeline made_locked();
};

}  // namespace lagoon::vk
