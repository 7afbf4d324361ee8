#include "render/passes/wakes_pass.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "gltf/gltf_loader.h"
#include "vk/barriers.h"

namespace lagoon::render {
namespace {

// More steps than this ahead of the last frame are a jump: prepare() runs them in its own submission.
constexpr long long kStepsPerFrame = 8;

std::vector<glm::dvec2> waypoints(const scene::VehiclePath& path) {
  std::vector<glm::dvec2> out;
  for (const glm::vec2& w : path.waypoints) out.emplace_back(w);
  return out;
}

}  // namespace

Result<std::unique_ptr<WakesPass>> WakesPass::create(vk::Context& ctx, const scene::Scene& scene) {
  std::unique_ptr<WakesPass> pass(new WakesPass());
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
  if (!scene.wakes.enabled) return pass;
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene.vehicles[v];
    if (vehicle.wake_strength <= 0) continue;
    auto model = gltf::load_gltf(vehicle.file);
    if (!model) return make_error("vehicles[" + std::to_string(v) + "].file: " + model.error().message);
    // The hull's footprint: a Gaussian whose ±2 sigma span its length and beam, as deep at its centre as
    // the model reaches below its waterline (its origin) at the surface, or as its height when submerged.
    const glm::dvec3 lo = glm::dvec3(model->bounds_min) * double(vehicle.scale);
    const glm::dvec3 hi = glm::dvec3(model->bounds_max) * double(vehicle.scale);
    const bool submerged = vehicle.depth_m > 0;
    const double reach = submerged ? hi.y - lo.y : std::max(-lo.y, 0.0);
    pass->hulls_.push_back({physics::WaypointPath(waypoints(vehicle.path), vehicle.path.loop,
                                                  vehicle.path.speed_mps, vehicle.path.start_m),
                            glm::dvec2(std::max(hi.z - lo.z, 1e-3) / 4, std::max(hi.x - lo.x, 1e-3) / 4),
                            reach * double(vehicle.wake_strength),
                            submerged ? double(vehicle.depth_m) : 0.0});
  }
  if (pass->hulls_.empty()) return pass;
  const scene::Wakes& w = scene.wakes;
  pass->step_s_ = double(w.step_s);
  pass->history_steps_ = (long long)std::ceil(double(w.history_s) / pass->step_s_);
  pass->layer_ = std::make_unique<ocean::DynamicLayerGpu>(
      ctx, ocean::DynamicLayerParams{.n = w.resolution,
                                     .cell_m = double(w.cell_size_m),
                                     .depth_m = double(scene.ocean.depth_m),
                                     .decay_per_s = double(w.damping_per_s),
                                     .sponge_m = double(w.border_m)});
  return pass;
}

glm::vec4 WakesPass::window() const {
  if (!layer_) return glm::vec4(0.0f);
  const double cell = layer_->params().cell_m;
  const glm::ivec2 o = layer_->window();
  return glm::vec4(float(o.x * cell), float(o.y * cell), float(layer_->params().n * cell), float(cell));
}

std::vector<ocean::WakeSource> WakesPass::sources(double t) const {
  std::vector<ocean::WakeSource> out;
  for (const Hull& h : hulls_) {
    const physics::TrackPoint p = h.path.at(t);
    out.push_back({.centre = p.position,
                   .velocity = p.velocity,
                   .heading = p.heading,
                   .sigma = h.sigma,
                   .depression = h.depression,
                   .depth = h.depth});
  }
  return out;
}

long long WakesPass::target_step(const scene::Scene& scene) const {
  // step_s is a float in the scene (0.1f is 0.10000000149): 9 s / 0.1f is 89.9999987 steps, meant as 90.
  return (long long)std::floor(std::max(double(scene.time_s), 0.0) / step_s_ + 1e-4);
}

void WakesPass::follow_camera(const scene::Scene& scene) {
  if (!layer_) return;
  const double cell = layer_->params().cell_m, width = layer_->params().n * cell;
  // Most of the window lies ahead of the camera, where it looks: its centre 0.35 of its width ahead (the
  // camera stays inside, 0.15 of the width from the window's edge; straight down, it is the centre).
  glm::dvec2 ahead(scene.camera.look_at.x - scene.camera.position.x,
                   scene.camera.look_at.z - scene.camera.position.z);
  const double length = glm::length(ahead);
  ahead = length > 1e-6 ? ahead / length : glm::dvec2(0.0);
  const glm::dvec2 centre =
      glm::dvec2(scene.camera.position.x, scene.camera.position.z) + 0.35 * width * ahead;
  const int half = int(layer_->params().n / 2);
  layer_->set_window({int(std::floor(centre.x / cell)) - half, int(std::floor(centre.y / cell)) - half});
}

void WakesPass::record_steps(VkCommandBuffer cmd, long long to) {
  for (; steps_done_ < to; ++steps_done_) {
    const double t = double(steps_done_) * step_s_;
    const std::vector<ocean::WakeSource> now = sources(t);
    layer_->record_step(cmd, step_s_, now);
  }
}

void WakesPass::prepare(vk::Context& ctx, const scene::Scene& scene) {
  if (!layer_) return;
  const long long target = target_step(scene);
  if (steps_done_ >= 0 && target >= steps_done_ && target - steps_done_ <= kStepsPerFrame) return;
  follow_camera(scene);
  steps_done_ = std::max(0LL, target - history_steps_);
  // The sources ring holds kStepsInFlight steps: a longer history is run in several submissions.
  bool clear = true;
  while (clear || steps_done_ < target) {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      if (clear) layer_->record_clear(cmd);
      record_steps(cmd, std::min(target, steps_done_ + (long long)ocean::DynamicLayerGpu::kStepsInFlight));
    });
    clear = false;
  }
}

void WakesPass::record(const FrameContext& frame) {
  if (!layer_) return;
  vk::GpuScope scope(frame.timer(), frame.cmd, "wakes");
  record_steps(frame.cmd, std::min(target_step(frame.scene), steps_done_ + kStepsPerFrame));
  // Drawn by the vertex and fragment stages, and read by the caustics' compute pass.
  vk::memory_barrier(frame.cmd, vk::access::kComputeWrite,
                     {vk::access::kGraphicsSampled.stage | vk::access::kComputeRead.stage,
                      vk::access::kGraphicsSampled.access | vk::access::kComputeRead.access});
}

}  // namespace lagoon::render
