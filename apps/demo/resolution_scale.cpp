#include "resolution_scale.h"

#include <algorithm>
#include <cmath>

namespace lagoon::demo {

void ResolutionScale::set_target_fps(double fps) {
  target_fps_ = std::max(fps, 0.0);
  if (target_fps_ == 0) scale_ = 1.0;
  smoothed_ms_ = 0;
  frames_at_scale_ = 0;
}

VkExtent2D ResolutionScale::render_extent(VkExtent2D window) const {
  return {std::max(1u, uint32_t(std::lround(window.width * scale_))),
          std::max(1u, uint32_t(std::lround(window.height * scale_)))};
}

void ResolutionScale::observe(double frame_ms) {
  if (target_fps_ == 0 || !(frame_ms > 0) || !std::isfinite(frame_ms)) return;
  // The first frame at a new size pays for its new targets: it is not the size's cost.
  if (++frames_at_scale_ == 1) return;
  smoothed_ms_ = smoothed_ms_ == 0 ? frame_ms : 0.7 * smoothed_ms_ + 0.3 * frame_ms;
  const double target_ms = 1000.0 / target_fps_;
  // Settling keeps the size steady near the target; a frame over twice the target's time is plainly too
  // slow, and waiting kSettleFrames of them would cost the user seconds where frames take hundreds of ms.
  if (frames_at_scale_ < kSettleFrames && smoothed_ms_ < kFarOver * target_ms) return;
  const double wanted = std::clamp(scale_ * std::sqrt(target_ms / smoothed_ms_), kLowest, 1.0);
  // Down to the step below what meets the target; up only when a whole step more still meets it.
  const double next = std::clamp(std::floor(wanted / kStep + 1e-9) * kStep, kLowest, 1.0);
  if (std::abs(next - scale_) < kStep / 2) return;
  scale_ = next;
  smoothed_ms_ = 0;
  frames_at_scale_ = 0;
}

}  // namespace lagoon::demo
