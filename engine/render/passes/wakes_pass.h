// The wakes (issue 14, docs/physics.md "Wakes"): the dynamic wave layer
// (compute/ocean/gpu/dynamic_layer_gpu.h) on a window where the camera looks, forced by every vehicle's hull
// along its path (world/vehicle_wakes.h), stepped at wakes.step_s to the frame's time. Its fields (h, dh/dx,
// dh/dz, foam trails) are added to the ocean's wherever the surface is drawn (render/surface_fields.h,
// shaders/common/wake_fields.glsl). Without vehicles, or with wakes.enabled false, it is inactive: a 1 x 1
// zero image is bound and the shaders compile the lookups out.
#pragma once
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/result.h"
#include "ocean/gpu/dynamic_layer_gpu.h"
#include "render/frame_context.h"
#include "scene/scene.h"
#include "vk/context.h"
#include "vk/image.h"
#include "world/vehicle_wakes.h"

namespace lagoon::render {

class WakesPass {
 public:
  // Fails naming the field when a vehicle's model cannot be read. The hulls follow `tracks`.
  static Result<std::unique_ptr<WakesPass>> create(vk::Context& ctx, const scene::Scene& scene,
                                                   world::VehicleTracks tracks = {});

  bool active() const { return layer_ != nullptr; }
  // (h, dh/dx, dh/dz, foam trails) of the layer (ocean/gpu/dynamic_layer_gpu.h), or a 1 x 1 zero image.
  const vk::Image& fields() const { return layer_ ? layer_->fields() : idle_; }
  // FrameUniforms.wakes: the window's corner (x, z) in metres, its width, the cell size.
  glm::vec4 window() const;

  // When the frame's time jumps (the first frame, backwards, or further ahead than wakes.history_s), runs
  // the layer from rest wakes.history_s before it (VehicleWakes::first_step_for) in its own submission and
  // waits, or takes the state an identical run of an earlier process left (render/wakes_cache.h). A frame
  // more than a few steps ahead but within the history steps on to it here, in its window as it is; with
  // `sequence` any frame ahead does. Call before recording the frame.
  void prepare(vk::Context& ctx, const scene::Scene& scene, bool sequence = false);
  // Puts the window where the camera looks (VehicleWakes::window_for; waves in the cells both windows share
  // are kept). Call before the frame's uniforms are written (window()).
  void follow_camera(const scene::Scene& scene);
  // Steps the layer to the frame's time.
  void record(const FrameContext& frame);

  // The vehicles' hulls on the water at time t.
  std::vector<ocean::WakeSource> sources(double t) const { return hulls_.sources(t); }
  // For tests: the layer itself (null when inactive), the steps it went through since it was made (recorded,
  // or restored from the cache), and how many of them were restored.
  const ocean::DynamicLayerGpu* layer() const { return layer_.get(); }
  long long steps_taken() const { return steps_taken_; }
  long long steps_from_cache() const { return steps_from_cache_; }

 private:
  explicit WakesPass(world::VehicleWakes hulls) : hulls_(std::move(hulls)) {}
  void record_steps(VkCommandBuffer cmd, long long to);
  // Steps to `to` in submissions of at most kStepsInFlight, from rest when `clear`.
  void run_to(vk::Context& ctx, long long to, bool clear);
  // Steps from rest (steps_done_) to `to`, or restores what an identical earlier run filed.
  void run_history(vk::Context& ctx, long long to);

  world::VehicleWakes hulls_;
  std::unique_ptr<ocean::DynamicLayerGpu> layer_;
  vk::Image idle_;
  long long steps_done_ = -1;  // the layer is at steps_done_ · step_s; < 0 before the first prepare
  long long steps_taken_ = 0, steps_from_cache_ = 0;
};

}  // namespace lagoon::render
