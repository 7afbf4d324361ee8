// The ocean step (compute/ocean/gpu): evolves the cascades to the frame's time and rebuilds their mips. The
// frame's first pass; its textures are ready for sampling by every later pass when it returns
// (GpuOcean::record_step's own barriers).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/frame_context.h"
#include "vk/context.h"

namespace lagoon::render {

class OceanStepPass {
 public:
  // Before a still frame the ocean runs at least this long (in kWarmupStep steps) so foam has built up; for
  // the FFT ocean as long as its foam lasts (warmup_s()).
  static constexpr double kWarmupS = 3.0;
  static constexpr double kWarmupStep = 0.1;
  // The FFT ocean makes foam only at the ticks of its clock, the multiples of kWarmupStep: the steps between
  // ticks only fade it, and a step that passes ticks first makes their foam (foam-only steps at the ticks).
  // So foam does not depend on how often a run steps: a demo at 60 Hz, a sequence at 30 fps and a still
  // frame's warm-up make the same foam, and with foam that lasts at most warmup_s() (shared/foam.h) a still
  // frame shows what a live run shows at the same time.
  double warmup_s() const;

  // Fails with the parameter's message when the scene's ocean is invalid (ocean/validate.h).
  static Result<OceanStepPass> create(vk::Context& ctx, const ocean::OceanParams& params);

  // Set-up work outside the frame: when `time_s` jumps (first frame, backwards, or more than kWarmupS ahead;
  // with `sequence` only the first two, and the frame's step then spans the gap), runs the warm-up from
  // still water in its own submission and waits, so the frame depends on `time_s` alone; or takes the foam an
  // identical warm-up of an earlier run left (foam_cache.h). Call before recording the frame for `time_s`.
  void prepare(vk::Context& ctx, double time_s, bool sequence = false);
  // Steps to frame.scene.time_s (from wherever prepare() or the last frame left the ocean).
  void record(const FrameContext& frame);

  const ocean::GpuOcean& ocean() const { return *ocean_; }
  // Whether the last step recorded was to `time_s` (the cascades hold that time).
  bool holds(double time_s) const { return time_s_ == time_s; }

 private:
  explicit OceanStepPass(std::unique_ptr<ocean::GpuOcean> ocean) : ocean_(std::move(ocean)) {}
  bool ticks() const { return ocean_->params().model == ocean::SurfaceModel::Fft; }
  void prepare_ticks(vk::Context& ctx, double t);
  // From still water (restart), the foam-only `steps` up to t, or the foam an identical warm-up filed.
  void warm_up(vk::Context& ctx, double t, const std::vector<double>& steps, double length_s);
  void record_ticks(const FrameContext& frame);

  std::unique_ptr<ocean::GpuOcean> ocean_;
  double time_s_ = -1;          // of the last step recorded; < 0 before the first
  std::string spectra_digest_;  // of the ocean's spectra, for the foam cache's key (render/foam_cache.h)
};

}  // namespace lagoon::render
