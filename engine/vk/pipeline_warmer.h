// Makes a list of pipelines on a thread of its own while the caller goes on (vk/pipeline_registry.h): from
// the last to the first, because whoever records a frame makes the ones it needs from the first, as it
// needs them; each is made once, by whichever comes first (the other waits on its lock), so the two meet
// in the middle. Destroying the warmer stops it after the pipeline it is making and joins it: it must go
// before the pipelines' owners and the device do.
#pragma once
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include "vk/pipeline_recipe.h"

namespace lagoon::vk {

class PipelineWarmer {
 public:
  PipelineWarmer() = default;
  explicit PipelineWarmer(std::vector<std::shared_ptr<PipelineRecipe>> recipes);
  ~PipelineWarmer();
  PipelineWarmer(const PipelineWarmer&) = delete;
  PipelineWarmer& operator=(const PipelineWarmer&) = delete;

  // Stops after the pipeline being made and waits for that.
  void stop();
  // Waits until every pipeline of the list is made.
  void wait();

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace lagoon::vk
