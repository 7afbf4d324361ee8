#include "render/wakes_cache.h"

#include "render/cached_tables.h"
#include "render/device_key.h"

namespace lagoon::render {

io::ResultKey wakes_key(const vk::Context& ctx, const ocean::DynamicLayerGpu& layer, const WakesRun& run) {
  const ocean::DynamicLayerParams& p = layer.params();
  io::ResultKey key = table_key("wakes");
  add_device(key, ctx);
  key.add("n", double(p.n)).add("cell", p.cell_m).add("gravity", p.gravity).add("depth", p.depth_m);
  key.add("decay", p.decay_per_s).add("sponge", p.sponge_m).add("sponge_rate", p.sponge_per_s);
  key.add("foam_lifetime", p.foam_lifetime_s).add("foam_spread", p.foam_spread_m2_s);
  key.add("window_x", double(layer.window().x)).add("window_z", double(layer.window().y));
  key.add("step", run.step_s).add("first", double(run.first_step)).add("last", double(run.last_step));
  std::vector<double> sources;
  for (const std::vector<ocean::WakeSource>& step : run.sources) {
    sources.push_back(double(step.size()));
    for (const ocean::WakeSource& s : step)
      sources.insert(sources.end(), {s.centre.x, s.centre.y, s.velocity.x, s.velocity.y, s.heading, s.sigma.x,
                                     s.sigma.y, s.depression, s.depth, s.foam_per_s});
  }
  key.add("sources", sources);
  return key;
}

std::optional<std::vector<float>> load_wakes(const io::ResultKey& key, const ocean::DynamicLayerGpu& layer) {
  return io::ResultCache::from_environment().load_vector<float>(key, layer.state_floats());
}

void store_wakes(const io::ResultKey& key, vk::Context& ctx, const ocean::DynamicLayerGpu& layer) {
  const io::ResultCache cache = io::ResultCache::from_environment();
  if (!cache.enabled()) return;
  // 7 MB each at 512²: few are kept (a dataset's shards share one; every still frame at another time is
  // another).
  constexpr size_t kKept = 8;
  cache.store_vector(key, layer.read_state(ctx), kKept);
}

}  // namespace lagoon::render
