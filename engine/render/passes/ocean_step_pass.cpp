#include "render/passes/ocean_step_pass.h"

#include <algorithm>
#include <vector>

#include "render/foam_cache.h"

namespace lagoon::render {

Result<OceanStepPass> OceanStepPass::create(vk::Context& ctx, const ocean::OceanParams& params) {
  auto ocean = ocean::GpuOcean::create(ctx, params);
  if (!ocean) return ocean.error();
  return OceanStepPass(std::move(*ocean));
}

void OceanStepPass::prepare(vk::Context& ctx, double t, bool sequence) {
  // A second frame at the same t (the ground truth's) steps by dt = 0, which leaves the foam as it is:
  // max(foam, new) with nothing decayed.
  if (time_s_ >= 0 && t >= time_s_ && (sequence || t - time_s_ <= kWarmupS)) return;
  ocean_->restart();
  // A still frame needs the foam a running ocean would have: run the last few seconds first, or take what
  // an earlier run's identical warm-up left (render/foam_cache.h).
  std::vector<double> steps = {t - kWarmupS};
  for (double step = steps.back() + kWarmupStep; step < t - 1e-9; step += kWarmupStep) steps.push_back(step);
  if (spectra_digest_.empty()) spectra_digest_ = spectra_digest(*ocean_);
  const io::ResultKey key =
      foam_key(ctx, *ocean_, spectra_digest_, {.time_s = t, .length_s = kWarmupS, .step_s = kWarmupStep});
  if (auto foam = load_foam(key, *ocean_); foam && ocean_->write_foam(*foam)) {
    time_s_ = steps.back();
  } else {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      double previous = steps.front();
      // The warm-up's textures are not drawn: its steps bring the foam alone to their time (GpuOcean::Step).
      for (double step : steps) {
        ocean_->record_step(cmd, step, step - previous, nullptr, ocean::GpuOcean::Step::WarmUp);
        previous = step;
      }
    });
    time_s_ = steps.back();
    if (ocean_->params().model != ocean::SurfaceModel::Springs) store_foam(key, ocean_->read_foam());
  }
}

void OceanStepPass::record(const FrameContext& frame) {
  const double t = frame.scene.time_s;
  // Without prepare() the first step starts foam from nothing (dt = 0), as GpuOcean's first step does.
  const double dt = time_s_ < 0 ? 0.0 : std::max(0.0, t - time_s_);
  ocean_->record_step(frame.cmd, t, dt, frame.timer());
  time_s_ = t;
}

}  // namespace lagoon::render
