#include "render/ocean_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <future>

#include "core/stage_times.h"
#include "render/camera.h"
#include "render/passes/caustics_pass.h"
#include "render/passes/objects_pass.h"
#include "render/passes/ocean_step_pass.h"
#include "render/passes/particles_pass.h"
#include "render/passes/refraction_pass.h"
#include "render/passes/sky_pass.h"
#include "render/passes/surface_pass.h"
#include "render/passes/underwater_pass.h"
#include "render/passes/wakes_pass.h"
#include "render/passes/waterline_pass.h"
#include "render/pipeline_memory.h"
#include "render/sky_light.h"
#include "render/surface_grid.h"
#include "scene/scene_io.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

static_assert(OceanRenderer::kWarmupS == OceanStepPass::kWarmupS);

const ocean::GpuOcean& OceanRenderer::ocean() const {
  return ocean_step_->ocean();
}

struct OceanRenderer::OwnTargets {
  vk::Image color, depth;
  vk::Buffer readback;  // the tone-mapped colour, copied in the frame's own submit
};

OceanRenderer::OceanRenderer(vk::Context& ctx) : ctx_(ctx), samplers_(Samplers::create(ctx)) {
  for (FrameSlot& slot : slots_) {
    slot.frame = vk::Buffer::create(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                    vk::MemoryUsage::Upload, "frame");
    slot.lights =
        vk::Buffer::create(ctx, sizeof(gpu::PointLightGpu) * LAGOON_MAX_LIGHTS,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Upload, "point lights");
    slot.sediment = vk::Buffer::create(
        ctx, sizeof(gpu::SedimentHeader) + sizeof(gpu::SedimentPuffGpu) * LAGOON_MAX_SEDIMENT_PUFFS,
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Upload, "sediment");
    slot.timer = vk::GpuTimer(ctx, 32);
    slot.surface_indices =
        vk::Buffer::create(ctx, kClipmapMaxIndices * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                           vk::MemoryUsage::Upload, "surface indices");
  }
}

OceanRenderer::~OceanRenderer() = default;

Result<std::unique_ptr<OceanRenderer>> OceanRenderer::create(vk::Context& ctx, const scene::Scene& scene,
                                                             world::VehicleTracks tracks) {
  std::unique_ptr<OceanRenderer> renderer(new OceanRenderer(ctx));
  if (auto r = renderer->init(scene, std::move(tracks)); !r) return r.error();
  return renderer;
}

Result<void> OceanRenderer::init(const scene::Scene& scene, world::VehicleTracks tracks) {
  StageTimer t_ocean("ocean spectra and pipelines");
  auto ocean_step = OceanStepPass::create(ctx_, scene.ocean);
  if (!ocean_step) return make_error("ocean: " + ocean_step.error().message);
  ocean_step_ = std::make_unique<OceanStepPass>(std::move(*ocean_step));
  shading_ = ocean_shading(ocean());
  caustic_mss_ = shading_.caustic_mss;
  t_ocean.end();
  StageTimer t_luts("water LUTs");
  auto luts = upload_water_luts(ctx_, scene, &ocean().spectra());  // the spectra the ocean step built
  if (!luts) return luts.error();
  luts_ = std::move(*luts);
  t_luts.end();
  StageTimer t_objects("scene objects");
  auto objects = SceneObjects::load(ctx_, scene, samplers_, kColorFormat, kHdrFormat, kDepthFormat);
  if (!objects) return objects.error();
  objects_ = std::move(*objects);
  t_objects.end();
  StageTimer t_world("bodies, wakes, sediment");
  auto world = world::World::create(
      scene, ocean().params(), ocean().spectra(),
      {.tracks = std::move(tracks), .camera_reach_m = double(shading_.bound.vertical_m)});
  if (!world) return world.error();
  world_ = std::move(*world);
  auto wakes = WakesPass::create(ctx_, scene, world_->tracks());
  if (!wakes) return wakes.error();
  wakes_ = std::move(*wakes);
  t_world.end();
  StageTimer t_passes("passes");
  fields_.emplace(SurfaceFields{ocean(), *wakes_, !world_->sediment().empty()});
  refraction_ = std::make_unique<RefractionPass>(ctx_, *objects_, kHdrFormat, kDepthFormat);
  reflection_ = std::make_unique<ObjectsPass>(ctx_, *objects_, gpu::MeshMode::Mirrored, "reflection",
                                              kHdrFormat, kDepthFormat);
  surface_ =
      std::make_unique<SurfacePass>(ctx_, *fields_, *objects_, luts_, samplers_, kColorFormat, kDepthFormat);
  sky_ = std::make_unique<SkyPass>(ctx_, kColorFormat, kDepthFormat);
  caustics_ = std::make_unique<CausticsPass>(ctx_, *fields_, samplers_);
  particles_ =
      std::make_unique<ParticlesPass>(ctx_, luts_, samplers_, kColorFormat, kDepthFormat,
                                      !world_->sediment().empty() && scene.sediment.grains_per_g > 0);
  waterline_ = std::make_unique<WaterlinePass>(ctx_, *fields_, samplers_, kColorFormat, kDepthFormat);
  window_ = std::make_unique<ObjectsPass>(ctx_, *objects_, gpu::MeshMode::Window, "snell window", kHdrFormat,
                                          kDepthFormat);
  underwater_ =
      std::make_unique<UnderwaterPass>(ctx_, *fields_, luts_, samplers_, kColorFormat, kDepthFormat);
  t_passes.end();
  // What the last runs of this scene made is made meanwhile on another thread: the warm-up and the first
  // frame's recording ask for it (~300 ms of lavapipe's CPU for the bay's frame).
  pipeline_memory_ = std::make_unique<PipelineMemory>(ctx_, scene);
  warmer_ = std::make_unique<vk::PipelineWarmer>(ctx_.pipelines().find(pipeline_memory_->remembered()));
  return {};
}

void OceanRenderer::remember_pipelines() {
  if (pipeline_memory_) pipeline_memory_->update(ctx_);
}

void OceanRenderer::prepare(const scene::Scene& scene) {
  StageTimer t("warm-up (foam, wakes)");
  // A jump in time (a still frame at a late time, a dataset's frame) has the floating bodies' physics replay
  // as much history on the CPU as the device does: it runs on another thread meanwhile, while this one only
  // waits for the device. The frames of a live loop take a step or two, inline (begin_frame).
  constexpr long long kJumpSteps = 120;  // a second of physics
  std::future<void> bodies;
  if (!world_->bodies().empty() && world_->bodies().steps_to(scene.time_s) >= kJumpSteps)
    bodies =
        std::async(std::launch::async, [this, time_s = scene.time_s] { world_->bodies().advance(time_s); });
  // Each part timed on its own too: a late or first frame's wait is mostly one of them.
  StageTimer t_foam("warm-up: foam");
  ocean_step_->prepare(ctx_, scene.time_s, history_ == History::Sequence);
  t_foam.end();
  StageTimer t_wakes("warm-up: wakes' history");
  wakes_->prepare(ctx_, scene, history_ == History::Sequence);
  t_wakes.end();
  StageTimer t_bodies("warm-up: bodies, remainder");
  if (bodies.valid()) {
    // Waiting, this thread makes the pipelines the last run used from the first on, as the warmer does from
    // the last on (a dataset's first frame waits here for ~0.5 s of the harbour's physics).
    if (pipeline_memory_)
      for (const auto& recipe : ctx_.pipelines().find(pipeline_memory_->remembered())) {
        if (bodies.wait_for(std::chrono::seconds(0)) == std::future_status::ready) break;
        recipe->made();
      }
    bodies.get();  // rethrows what the physics threw
  }
}

void OceanRenderer::advance(const scene::Scene& scene) {
  prepare(scene);
  move_world(scene);
  FrameSlot& slot = slots_[0];
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kAllCommands, vk::access::kAllCommands);
    slot.timer.reset(cmd);
    const FrameContext frame{
        .cmd = cmd, .extent = {scene.render.width, scene.render.height}, .scene = scene, .slot = slot};
    record_frame(frame, {.kind = FrameKind::Advance});
  });
}

void OceanRenderer::move_world(const scene::Scene& scene) {
  place_floating_objects(scene.time_s);
  wakes_->follow_camera(scene);
}

world::CameraSide OceanRenderer::camera_side(const scene::Scene& scene, VkExtent2D extent) {
  const float aspect = float(extent.width) / float(extent.height);
  const double lens_m = scene.camera.near_m * std::tan(0.5 * glm::radians(double(scene.camera.fov_deg))) *
                        std::sqrt(1.0 + double(aspect) * aspect);
  return world_->camera_medium().side(scene.camera.position, lens_m, scene.time_s);
}

FrameContext OceanRenderer::begin_frame(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent,
                                        uint32_t slot_index, const CausticsWindow& caustics) {
  FrameSlot& slot = slots_[slot_index % kSlots];
  const world::CameraSide side = camera_side(scene, extent);
  move_world(scene);
  objects_->set_sky(sky_light(scene.sun));
  const uint32_t light_count =
      write_point_lights(scene, objects_->gltf_lights(reference_illuminance_lux(scene.sun)),
                         reinterpret_cast<gpu::PointLightGpu*>(slot.lights.mapped()));
  slot.lights.flush();
  write_sediment(scene.time_s, slot);
  const CameraMatrices cam = camera_matrices(scene.camera, float(extent.width) / float(extent.height));
  const float reach = std::min(0.8f * scene.camera.far_m, 3000.0f);
  // Under the water the surface is seen through at least as much water as it is far away, and beyond the
  // underwater tables' reach the water lets through less than 1e-3 of any light (optics/underwater.h): the
  // mesh stops there. On lavapipe each triangle's set-up costs ~3 us on one thread; this saves a third.
  const float mesh_reach = side == world::CameraSide::Below ? std::min(reach, float(luts_.d_max_m)) : reach;
  const SurfaceGrid grid = surface_grid(scene.camera.position, mesh_reach, &cam.view_proj, shading_.bound);
  slot.surface_index_count = uint32_t(grid.indices.size());
  std::memcpy(slot.surface_indices.mapped(), grid.indices.data(), grid.indices.size() * sizeof(uint32_t));
  slot.surface_indices.flush();
  const glm::vec4 submerged = objects_->submerged_screen_rect(cam.view_proj);
  const gpu::FrameUniforms uniforms = frame_uniforms({.scene = scene,
                                                      .extent = extent,
                                                      .ocean = ocean(),
                                                      .shading = shading_,
                                                      .luts = luts_,
                                                      .grid = grid,
                                                      .view_proj = cam.view_proj,
                                                      .reach_m = reach,
                                                      .light_count = light_count,
                                                      .under_water = side == world::CameraSide::Below,
                                                      .caustics = caustics,
                                                      .wakes_window = wakes_->window(),
                                                      .submerged_rect = submerged});
  std::memcpy(slot.frame.mapped(), &uniforms, sizeof(uniforms));
  slot.frame.flush();
  // Frames may be recorded while the previous one runs; they share the ocean's textures and the passes'
  // targets, so this frame's work starts after everything submitted before it.
  vk::memory_barrier(cmd, vk::access::kAllCommands, vk::access::kAllCommands);
  slot.timer.reset(cmd);
  return FrameContext{.cmd = cmd,
                      .extent = extent,
                      .scene = scene,
                      .slot = slot,
                      .camera_side = side,
                      .light_count = light_count,
                      .caustics = caustics.cells > 0,
                      // Any object under the water, on the screen or not: switching the variant as one
                      // comes into view would compile a pipeline in the middle of a run (memory, a stall).
                      .submerged_objects = submerged.x <= submerged.z};
}

void OceanRenderer::place_floating_objects(double time_s) {
  if (world_->bodies().empty()) return;
  world_->bodies().advance(time_s);
  for (const world::FloatingObjects::Pose& pose : world_->bodies().poses())
    objects_->place(pose.object, pose.model_to_world);
}

void OceanRenderer::write_sediment(double time_s, FrameSlot& slot) const {
  auto* header = reinterpret_cast<gpu::SedimentHeader*>(slot.sediment.mapped());
  auto* puffs = reinterpret_cast<gpu::SedimentPuffGpu*>(header + 1);
  if (world_->sediment().empty())
    *header = {};
  else
    world_->sediment().write(time_s, header, puffs);
  slot.sediment.flush();
}

void OceanRenderer::resize(VkExtent2D extent) {
  if (extent_.width == extent.width && extent_.height == extent.height) return;
  if (extent_.width != 0) ctx_.wait_idle();  // frames in flight may still use the old size
  views_drawn_for_.clear();                  // the targets are new
  refraction_->resize(extent);
  reflection_->resize(extent);
  window_->resize(extent);
  waterline_->resize(extent);
  extent_ = extent;
}

const OceanRenderer::OwnTargets& OceanRenderer::own_targets(VkExtent2D extent) {
  if (own_ && own_->color.extent().width == extent.width && own_->color.extent().height == extent.height)
    return *own_;
  if (own_) ctx_.wait_idle();
  own_.reset();  // free the old size first: the new one may be large
  vk::Image color =
      vk::Image::create(ctx_, {.format = kColorFormat,
                               .extent = extent,
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               .debug_name = "color"});
  vk::Buffer readback = vk::Buffer::create(ctx_, vk::readback_bytes(color), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           vk::MemoryUsage::Readback, "frame readback");
  vk::Image depth = vk::Image::create(ctx_, {.format = kDepthFormat,
                                             .extent = extent,
                                             .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                             .debug_name = "depth"});
  own_ = std::make_unique<OwnTargets>(
      OwnTargets{.color = std::move(color), .depth = std::move(depth), .readback = std::move(readback)});
  return *own_;
}

const vk::Image& OceanRenderer::record(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent,
                                       uint32_t slot) {
  const OwnTargets& own = own_targets(extent);
  record(cmd, scene,
         HostTargets{own.color.handle(), own.color.view(), own.depth.handle(), own.depth.view(), extent},
         slot);
  return own.color;
}

void OceanRenderer::record(VkCommandBuffer cmd, const scene::Scene& scene, const HostTargets& targets,
                           uint32_t slot) {
  resize(targets.extent);
  const CausticsWindow caustics =
      caustics_window(scene, sun_direction(scene.sun), float(scene.water.ior), caustic_mss_, caustic_cells_);
  const FrameContext frame = begin_frame(cmd, scene, targets.extent, slot, caustics);
  record_frame(frame, {.kind = FrameKind::Picture,
                       .caustics = caustics,
                       .color = {targets.color, targets.color_view, VK_IMAGE_ASPECT_COLOR_BIT},
                       .depth = {targets.depth, targets.depth_view, VK_IMAGE_ASPECT_DEPTH_BIT}});
  // A host's picture (the demo's) is not one a ground-truth frame follows: its key is not worth a frame's
  // time. render() files its own.
  views_drawn_for_.clear();
  picture_side_ = frame.camera_side;
  remember_pipelines();
}

void OceanRenderer::set_caustic_cells(uint32_t cells) {
  uint32_t allowed = LAGOON_CAUSTICS_CELLS;
  while (allowed > 64 && allowed > cells) allowed /= 2;
  if (allowed == caustic_cells_) return;
  caustic_cells_ = allowed;
  caustic_mss_ = allowed == LAGOON_CAUSTICS_CELLS
                     ? shading_.caustic_mss
                     : caustic_unresolved_mss(ocean(), CausticsWindow::kSizeM / float(allowed));
  views_drawn_for_.clear();  // a ground-truth frame after it draws its own map
}

void OceanRenderer::draw_for_code_only(const scene::Scene& scene) {
  pipeline_memory_.reset();  // this frame's pipelines are not the scene's (no warm-up)
  const VkExtent2D extent{scene.render.width, scene.render.height};
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) { record(cmd, scene, extent, 0); });
}

std::string OceanRenderer::views_key(const scene::Scene& scene, world::CameraSide side, VkExtent2D extent) {
  return scene::scene_to_json(scene, {}).dump() + " side " + std::to_string(int(side)) + " size " +
         std::to_string(extent.width) + "x" + std::to_string(extent.height);
}

std::vector<vk::PassTime> OceanRenderer::timings(uint32_t slot) const {
  return slots_[slot % kSlots].timer.results();
}

io::Image8 OceanRenderer::render(const scene::Scene& scene, std::vector<vk::PassTime>* timings) {
  const VkExtent2D extent{scene.render.width, scene.render.height};
  prepare(scene);
  const OwnTargets& own = own_targets(extent);
  StageTimer t("frame");
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    record(cmd, scene, extent, 0);
    vk::record_readback(cmd, own.color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        vk::access::kColorAttachmentWrite, own.readback);
  });
  if (timings) *timings = this->timings(0);
  views_drawn_for_ = views_key(scene, picture_side_, extent);
  remember_pipelines();
  own.readback.invalidate();
  io::Image8 image{.width = extent.width, .height = extent.height};
  image.rgba.resize(vk::readback_bytes(own.color));
  std::memcpy(image.rgba.data(), own.readback.mapped(), image.rgba.size());
  return image;
}

}  // namespace lagoon::render
