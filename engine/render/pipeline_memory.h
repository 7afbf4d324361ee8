// The pipelines a scene's frames make, remembered between runs (issue 32, a warm start): the keys
// (vk/pipeline_recipe.h) that earlier runs of the same scene on the same device made, kept in the result
// cache (io/result_cache.h) under the scene without its time, camera and size (a dataset's frames, the
// demo's camera and a still frame share them). A renderer has them made on another thread while it warms
// up and records its first frame (vk/pipeline_warmer.h): on lavapipe each is tens of milliseconds of the CPU
// even when Mesa's shader cache holds its code.
#pragma once
#include <string>
#include <vector>

#include "io/result_cache.h"
#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::render {

class PipelineMemory {
 public:
  PipelineMemory(const vk::Context& ctx, const scene::Scene& scene);
  // What the last run used, in the order it first used it (none the first time, or without the cache).
  const std::vector<std::string>& remembered() const { return remembered_; }
  // Files what the context's users have used since this memory was created (this renderer's frames), when
  // that differs from what was remembered (cheap when nothing was used since the last call: it may be called
  // every frame). Only this run's: a pipeline an earlier run needed (a cold run's foam warm-up) and this
  // one did not is not made ahead again.
  void update(const vk::Context& ctx);

  // At most this many are kept (the shipped scenes make 12-40).
  static constexpr size_t kMaxKeys = 256;

 private:
  io::ResultKey key_;
  std::vector<std::string> remembered_;
  size_t made_seen_ = 0;           // the context's used count at the last update
  std::vector<std::string> made_;  // used by this run, each once
};

}  // namespace lagoon::render
