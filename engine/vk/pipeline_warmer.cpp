#include "vk/pipeline_warmer.h"

namespace lagoon::vk {

PipelineWarmer::PipelineWarmer(std::vector<std::shared_ptr<PipelineRecipe>> recipes) {
  if (recipes.empty()) return;
  thread_ = std::thread([this, recipes = std::move(recipes)] {
    for (auto it = recipes.rbegin(); it != recipes.rend() && !stop_; ++it) {
      try {
        (*it)->made();
      } catch (...) {
        // Left unmade: its first use makes it again and reports the failure where it can be handled.
      }
    }
  });
}

void PipelineWarmer::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void PipelineWarmer::wait() {
  if (thread_.joinable()) thread_.join();
}

PipelineWarmer::~PipelineWarmer() {
  stop();
}

}  // namespace lagoon::vk
