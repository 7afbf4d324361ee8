// Dynamic resolution for the demo (issue 34): live frames are drawn at the fraction of the window's size that
// holds a target frame rate and stretched to the window. The fraction moves in eighths, down to a quarter,
// with a step of hysteresis and a few frames to settle between moves, so the renderer does not re-size its
// targets every frame; frames far slower than the target move it at once. A frame's cost is taken as
// proportional to its pixels; where a device's fixed costs (the ocean step, the bodies) keep the target out
// of reach, the fraction goes to its floor.
#pragma once
#include <vulkan/vulkan.h>

namespace lagoon::demo {

class ResolutionScale {
 public:
  static constexpr double kStep = 0.125, kLowest = 0.25;
  static constexpr int kSettleFrames = 6;
  // Frames slower than this many times the target move the size down at once, without settling.
  static constexpr double kFarOver = 2.0;

  // target_fps 0: always the window's size.
  explicit ResolutionScale(double target_fps = 15.0) { set_target_fps(target_fps); }
  void set_target_fps(double fps);
  double target_fps() const { return target_fps_; }

  // The fraction of the window's width and height to draw (kLowest .. 1, in steps of kStep).
  double scale() const { return scale_; }
  // The size to draw a window of `window` at: its width and height times scale(), at least 1 pixel.
  VkExtent2D render_extent(VkExtent2D window) const;
  // How many times coarser the caustic map's cells are for frames drawn at scale(): 1 from 3/4 of the window
  // up, 2 from 3/8, else 4 (OceanRenderer::set_caustic_cells). The map's work (its rays and blur) does not
  // shrink with the picture: at the floor on lavapipe it was most of a small frame's cost.
  int caustic_coarsening() const { return scale_ >= 0.75 ? 1 : scale_ >= 0.375 ? 2 : 4; }
  // One frame drawn at scale() took `frame_ms` (wall time, the whole loop). The scale that meets the target
  // is scale · sqrt(target / smoothed time), rounded down to a step.
  void observe(double frame_ms);

 private:
  double target_fps_ = 15.0;
  double scale_ = 1.0;
  double smoothed_ms_ = 0.0;  // 0: no frame seen at this scale yet
  int frames_at_scale_ = 0;
};

}  // namespace lagoon::demo
