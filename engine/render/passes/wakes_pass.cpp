#include "render/passes/wakes_pass.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "render/wakes_cache.h"
#include "vk/barriers.h"

namespace lagoon::render {
namespace {

// More steps than this ahead of the last frame are a jump: prepare() runs them in its own submission.
constexpr long long kStepsPerFrame = 8;

}  // namespace

Result<std::unique_ptr<WakesPass>> WakesPass::create(vk::Context& ctx, const scene::Scene& scene,
                                                     world::VehicleTracks tracks) {
  auto hulls = world::VehicleWakes::create(scene, std::move(tracks));
  if (!hulls) return hulls.error();
  std::unique_ptr<WakesPass> pass(new WakesPass(std::move(*hulls)));
  pass->idle_ = vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                        .extent = {1, 1},
                                        .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                        .debug_name = "no wakes"});
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, pass->idle_.handle(), pass->idle_.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_GENERAL, vk::access::kNone, vk::access::kTransferWrite);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange range = pass->idle_.all_subresources();
    vkCmdClearColorImage(cmd, pass->idle_.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kGraphicsSampled);
  });
  if (!pass->hulls_.empty())
    pass->layer_ = std::make_unique<ocean::DynamicLayerGpu>(ctx, pass->hulls_.params());
  return pass;
}

glm::vec4 WakesPass::window() const {
  if (!layer_) return glm::vec4(0.0f);
  const double cell = layer_->params().cell_m;
  const glm::ivec2 o = layer_->window();
  return glm::vec4(float(o.x * cell), float(o.y * cell), float(layer_->params().n * cell), float(cell));
}

void WakesPass::follow_camera(const scene::Scene& scene) {
  if (layer_) layer_->set_window(hulls_.window_for(scene.camera));
}

void WakesPass::record_steps(VkCommandBuffer cmd, long long to) {
  for (; steps_done_ < to; ++steps_done_) {
    const std::vector<ocean::WakeSource> now = hulls_.sources(double(steps_done_) * hulls_.step_s());
    layer_->record_step(
        cmd, hulls_.step_s(), now,
        steps_done_ + 1 == to ? ocean::DynamicLayerGpu::Fields::Write : ocean::DynamicLayerGpu::Fields::Keep);
    ++steps_taken_;
  }
}

void WakesPass::run_to(vk::Context& ctx, long long to, bool clear) {
  // The sources ring holds kStepsInFlight steps: a longer run is recorded in several submissions.
  while (clear || steps_done_ < to) {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      if (clear) layer_->record_clear(cmd);
      record_steps(cmd, std::min(to, steps_done_ + (long long)ocean::DynamicLayerGpu::kStepsInFlight));
    });
    clear = false;
  }
}

void WakesPass::prepare(vk::Context& ctx, const scene::Scene& scene, bool sequence) {
  if (!layer_) return;
  const long long target = hulls_.step_at(scene.time_s);
  if (steps_done_ >= 0 && target >= steps_done_) {
    if (target - steps_done_ <= kStepsPerFrame) return;  // the frame's own steps (record)
    // A live frame further ahead steps on too while the layer is no older than the step a replay would start
    // from rest (stepping on is then no longer): on a device slower than kStepsPerFrame steps a frame, each
    // frame replaying the whole history made the next one later still (0.1 frames/s at 1 s a frame in the
    // harbour on lavapipe).
    if (sequence || steps_done_ >= hulls_.first_step_for(scene.time_s)) return run_to(ctx, target, false);
  }
  follow_camera(scene);
  steps_done_ = hulls_.first_step_for(scene.time_s);
  run_history(ctx, target);
}

void WakesPass::run_history(vk::Context& ctx, long long to) {
  const long long first = steps_done_;
  if (to <= first) return run_to(ctx, to, true);
  std::vector<std::vector<ocean::WakeSource>> sources;
  for (long long s = first; s < to; ++s) sources.push_back(hulls_.sources(double(s) * hulls_.step_s()));
  const io::ResultKey key = wakes_key(
      ctx, *layer_, {.step_s = hulls_.step_s(), .first_step = first, .last_step = to, .sources = sources});
  if (std::optional<std::vector<float>> state = load_wakes(key, *layer_);
      state && layer_->write_state(ctx, *state)) {
    steps_done_ = to;
    steps_taken_ += to - first;
    steps_from_cache_ += to - first;
    return;
  }
  run_to(ctx, to, true);
  store_wakes(key, ctx, *layer_);
}

void WakesPass::record(const FrameContext& frame) {
  if (!layer_) return;
  vk::GpuScope scope(frame.timer(), frame.cmd, "wakes");
  record_steps(frame.cmd, std::min(hulls_.step_at(frame.scene.time_s), steps_done_ + kStepsPerFrame));
  // Drawn by the vertex and fragment stages, and read by the caustics' compute pass.
  vk::memory_barrier(frame.cmd, vk::access::kComputeWrite,
                     {vk::access::kGraphicsSampled.stage | vk::access::kComputeRead.stage,
                      vk::access::kGraphicsSampled.access | vk::access::kComputeRead.access});
}

}  // namespace lagoon::render
