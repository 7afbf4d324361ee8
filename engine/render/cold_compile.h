// A first run's pipelines compiled on two cores (issue 32, a cold start). On a CPU device (lavapipe) LLVM
// makes a pipeline's machine code when a command buffer first uses it, on the device's one queue thread, and
// Mesa files it in its shader cache: a cold first frame of the default scene spends most of its seconds
// there, on one core, first for the foam warm-up's pipelines, then for the frame's. A ColdCompile draws the
// frame on a second device, on a thread of its own and without the warm-up, while the renderer on the first
// device warms up; when that one draws, much of the frame's code is in Mesa's cache. Nothing it draws is kept
// or read back.
//
// It starts only on a CPU device, and only until this build has finished a frame on this device once (a
// marker in the result cache, io/result_cache.h): after that Mesa's cache holds the code, and a second device
// would only compete for the cores. LAGOON_COLD_COMPILE=0 turns it off.
#pragma once
#include <cstdint>
#include <memory>
#include <thread>

#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::render {

class ColdCompile {
 public:
  // Null when it would not help: a GPU, a build that has drawn on this device before, no result cache, or
  // LAGOON_COLD_COMPILE=0. `options` are those `ctx` was made with (the second device is the same one).
  static std::unique_ptr<ColdCompile> start_if_cold(const vk::Context& ctx, vk::ContextOptions options,
                                                    const scene::Scene& scene);
  // Call after the first device's first frame: waits for the second device, drops it and, when neither
  // device reported a validation error, files the marker (this build has drawn on this device). Returns the
  // validation layer's errors on the second device (it drew the same frame, so they are the frame's); 0 and
  // nothing done when `cold` is null.
  static uint32_t finish(std::unique_ptr<ColdCompile>& cold, vk::Context& ctx);

  // Waits for the second device's frame (a cold run's renderer is slower still: it is never waited long).
  ~ColdCompile();
  ColdCompile(const ColdCompile&) = delete;
  ColdCompile& operator=(const ColdCompile&) = delete;

 private:
  ColdCompile() = default;
  static void mark_warm(const vk::Context& ctx);
  uint32_t join();
  void run(vk::ContextOptions options, scene::Scene scene);

  std::thread thread_;
  uint32_t validation_failures_ = 0;
};

}  // namespace lagoon::render
