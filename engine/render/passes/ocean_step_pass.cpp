#include "render/passes/ocean_step_pass.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ocean/whitecaps.h"
#include "render/foam_cache.h"

namespace lagoon::render {

Result<OceanStepPass> OceanStepPass::create(vk::Context& ctx, const ocean::OceanParams& params) {
  // The foam rule from the result cache when an earlier run of this sea worked it out (render/foam_cache.h).
  auto ocean = ocean::GpuOcean::create(ctx, params, ocean::FftVariant::Auto, cached_foam_rule);
  if (!ocean) return ocean.error();
  return OceanStepPass(std::move(*ocean));
}

namespace {

// The tick at or before t (a scene's float time may land a hair below a tick it means).
long long tick_at_or_before(double t) {
  return (long long)std::floor(t / OceanStepPass::kWarmupStep + 1e-4);
}
double tick_time(long long k) {
  return double(k) * OceanStepPass::kWarmupStep;
}
bool is_tick(double t) {
  return std::abs(t - tick_time(tick_at_or_before(t))) < 1e-4 * OceanStepPass::kWarmupStep;
}

}  // namespace

double OceanStepPass::warmup_s() const {
  if (!ticks()) return kWarmupS;
  // Capped: foam that never fades (decay 0) would need an endless warm-up; below ~0.15/s a still frame may
  // miss the oldest of a live run's foam.
  constexpr double kLongestWarmupS = 8.0;
  const double lasts = ocean::foam_memory_s(ocean_->params().foam.decay_per_s);
  return std::clamp(std::ceil(lasts / kWarmupStep) * kWarmupStep, kWarmupS, kLongestWarmupS);
}

void OceanStepPass::prepare(vk::Context& ctx, double t, bool sequence) {
  // A second frame at the same t (the ground truth's) steps by dt = 0, which leaves the foam as it is:
  // max(foam, new) with nothing decayed.
  if (time_s_ >= 0 && t >= time_s_ && (sequence || t - time_s_ <= warmup_s())) return;
  if (ticks()) return prepare_ticks(ctx, t);
  // A still frame needs the foam a running ocean would have: run the last few seconds first.
  std::vector<double> steps = {t - kWarmupS};
  for (double step = steps.back() + kWarmupStep; step < t - 1e-9; step += kWarmupStep) steps.push_back(step);
  warm_up(ctx, t, steps, kWarmupS);
}

void OceanStepPass::warm_up(vk::Context& ctx, double t, const std::vector<double>& steps, double length_s) {
  ocean_->restart();
  // Or take what an earlier run's identical warm-up left (render/foam_cache.h).
  if (spectra_digest_.empty()) spectra_digest_ = spectra_digest(*ocean_);
  const io::ResultKey key =
      foam_key(ctx, *ocean_, spectra_digest_, {.time_s = t, .length_s = length_s, .step_s = kWarmupStep});
  time_s_ = steps.back();
  if (auto foam = load_foam(key, *ocean_); foam && ocean_->write_foam(*foam)) return;
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    double previous = steps.front();
    // The warm-up's textures are not drawn: its steps bring the foam alone to their time (GpuOcean::Step).
    for (double step : steps) {
      ocean_->record_step(cmd, step, step - previous, nullptr, ocean::GpuOcean::Step::WarmUp);
      previous = step;
    }
  });
  if (ocean_->params().model != ocean::SurfaceModel::Springs) store_foam(key, ocean_->read_foam());
}

void OceanStepPass::record(const FrameContext& frame) {
  if (ticks()) return record_ticks(frame);
  const double t = frame.scene.time_s;
  // Without prepare() the first step starts foam from nothing (dt = 0), as GpuOcean's first step does.
  const double dt = time_s_ < 0 ? 0.0 : std::max(0.0, t - time_s_);
  ocean_->record_step(frame.cmd, t, dt, frame.timer());
  time_s_ = t;
}

void OceanStepPass::prepare_ticks(vk::Context& ctx, double t) {
  // The ticks of the last warmup_s() before t (a tick at t is the frame's own step's). The ocean then holds a
  // time before t: the frame's step is still to come.
  std::vector<double> steps;
  const long long last = is_tick(t) ? tick_at_or_before(t) - 1 : tick_at_or_before(t);
  for (long long k = tick_at_or_before(t - warmup_s()) + 1; k <= last; ++k) steps.push_back(tick_time(k));
  warm_up(ctx, t, steps, warmup_s());
}

void OceanStepPass::record_ticks(const FrameContext& frame) {
  const double t = frame.scene.time_s;
  // Without prepare() the first step makes foam from nothing at t, as GpuOcean's first step does.
  if (time_s_ < 0) {
    ocean_->record_step(frame.cmd, t, 0.0, frame.timer());
    time_s_ = t;
    return;
  }
  // The ticks passed since the last step make their foam (foam-only steps); those too long before t to show
  // at t are skipped, their fade composing into the next step's.
  const long long last = is_tick(t) ? tick_at_or_before(t) - 1 : tick_at_or_before(t);
  const long long first = std::max(tick_at_or_before(time_s_), tick_at_or_before(t - warmup_s())) + 1;
  if (first <= last) {
    // One scope for all of them: a slow frame passes many ticks, and the timer holds a few dozen scopes.
    vk::GpuScope scope(frame.timer(), frame.cmd, "ocean foam ticks");
    for (long long k = first; k <= last; ++k) {
      const double tick = tick_time(k);
      ocean_->record_step(frame.cmd, tick, std::max(0.0, tick - time_s_), nullptr,
                          ocean::GpuOcean::Step::WarmUp);
      time_s_ = tick;
    }
  }
  ocean_->record_step(frame.cmd, t, std::max(0.0, t - time_s_), frame.timer(), ocean::GpuOcean::Step::Full,
                      is_tick(t));
  time_s_ = t;
}

}  // namespace lagoon::render
