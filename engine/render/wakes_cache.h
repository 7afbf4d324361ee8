// The wakes' history (WakesPass::prepare: up to wakes.history_s of steps of the 512² layer before a still
// frame or a sequence's first, ~65 ms a step on lavapipe: 4.3 s before the harbour's first frame at 6 s)
// kept between runs in the result cache (io/result_cache.h), as the foam's warm-up is (render/foam_cache.h):
// a second process drawing the same wakes to the same step (a dataset's other shards, a re-run, the tests)
// starts from the state the first one's steps left, bit for bit. The key holds everything the steps compute
// from: the code's fingerprint, the device, the layer's parameters, its window, the steps' span and every
// step's sources (the hulls where their tracks put them).
#pragma once
#include <optional>
#include <span>
#include <vector>

#include "io/result_cache.h"
#include "ocean/gpu/dynamic_layer_gpu.h"
#include "vk/context.h"

namespace lagoon::render {

struct WakesRun {
  double step_s = 0;
  long long first_step = 0, last_step = 0;  // the steps [first_step, last_step) from rest
  // Each step's sources, in order.
  std::span<const std::vector<ocean::WakeSource>> sources;
};

io::ResultKey wakes_key(const vk::Context& ctx, const ocean::DynamicLayerGpu& layer, const WakesRun& run);

// The state an earlier run filed under `key` (DynamicLayerGpu::read_state), when there is one that fits.
std::optional<std::vector<float>> load_wakes(const io::ResultKey& key, const ocean::DynamicLayerGpu& layer);
// Files the layer's state (read back from the device only when the cache is on).
void store_wakes(const io::ResultKey& key, vk::Context& ctx, const ocean::DynamicLayerGpu& layer);

}  // namespace lagoon::render
