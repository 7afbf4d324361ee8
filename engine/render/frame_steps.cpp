// The frame, declared once (issue 35): every pass the renderer records, the frames it joins (the picture,
// the two ground-truth frames a dataset asks for, a step without drawing), the camera sides it runs for, and
// the images it reads and writes, stated where it records. The picture (record()), the ground-truth frames
// (render_surface_aov, render_underwater_terms) and advance() all record through kFrame below, so a pass
// added here reaches every frame that joins it, and a ground-truth frame cannot fall behind the picture.
#include <cstdint>
#include <initializer_list>

#include "render/float_targets.h"
#include "render/ocean_renderer.h"
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
#include "vk/barriers.h"
#include "vk/rendering.h"

namespace lagoon::render {

using enum vk::ImageUse;
using world::CameraSide;

namespace {

// The frame kinds (OceanRenderer::FrameKind values) in a mask.
template <typename Kind>
constexpr uint8_t kinds(std::initializer_list<Kind> list) {
  uint8_t mask = 0;
  for (Kind k : list) mask |= uint8_t(k);
  return mask;
}

constexpr uint8_t sides(std::initializer_list<CameraSide> list) {
  uint8_t mask = 0;
  for (CameraSide s : list) mask |= uint8_t(1u << unsigned(s));
  return mask;
}

constexpr uint8_t kEveryKind = 0xff, kEverySide = 0xff;
constexpr uint8_t kSeesSurface = sides({CameraSide::Above, CameraSide::Waterline});
constexpr uint8_t kInWater = sides({CameraSide::Waterline, CameraSide::Below});

}  // namespace

// The steps, each a pass with the images it hands on. Friends of OceanRenderer (its passes are private).
struct FrameSteps {
  using Kind = OceanRenderer::FrameKind;
  using Request = OceanRenderer::FrameRequest;

  // Writes: the ocean's cascades and the wakes' layer, to the frame's time (state every later frame carries).
  // A ground-truth frame at the picture's time finds the cascades there already: a step by dt = 0 would make
  // the same textures again (the foam: max(foam, new), nothing decayed), an ocean step per ground-truth
  // frame.
  static void time_steps(OceanRenderer& r, const FrameContext& f, const Request& q) {
    const bool ground_truth = q.kind == Kind::SurfaceAov || q.kind == Kind::UnderwaterTerms;
    if (!(ground_truth && r.ocean_step_->holds(f.scene.time_s))) r.ocean_step_->record(f);
    r.wakes_->record(f);
  }
  // Writes: the caustic map, ready for the fragment shaders (unless the request's frame has it already).
  static void caustics(OceanRenderer& r, const FrameContext& f, const Request& q) {
    if (!q.views_drawn) r.caustics_->record(f, q.caustics);
  }
  // Writes: what lies under the water (albedo and depth), sampled by the surface and the underwater view
  // (unless the request's frame has it already).
  static void refraction(OceanRenderer& r, const FrameContext& f, const Request& q) {
    if (q.views_drawn) return;
    vk::use(f.cmd, {r.refraction_->albedo(), r.refraction_->depth()}, Discard, Attachment);
    r.refraction_->record(f);
    vk::use(f.cmd, {r.refraction_->albedo(), r.refraction_->depth()}, Attachment, Sampled);
  }
  // Writes: what lies above the water as seen through Snell's window from under it.
  static void window(OceanRenderer& r, const FrameContext& f, const Request&) {
    vk::use(f.cmd, {r.window_->color(), r.window_->depth()}, Discard, Attachment);
    r.window_->record(f);
    vk::use(f.cmd, {r.window_->color(), r.window_->depth()}, Attachment, Sampled);
  }
  static UnderwaterPass::Inputs below(const OceanRenderer& r) {
    return {r.refraction_->albedo_image(), r.refraction_->depth_image(), r.caustics_->map(),
            r.window_->color_image()};
  }
  // Reads refraction, caustics, window. Writes: the picture, under the water.
  static void underwater(OceanRenderer& r, const FrameContext& f, const Request& q) {
    vk::use(f.cmd, {q.color, q.depth}, Discard, Attachment);
    r.underwater_->record(f, below(r), q.color, q.depth);
  }
  // Writes: the particles over the picture under the water.
  static void particles(OceanRenderer& r, const FrameContext& f, const Request& q) {
    vk::use(f.cmd, {q.color, q.depth}, Attachment, Attachment);
    r.particles_->record(f, q.color, q.depth);
  }
  // Writes: the objects above the water mirrored (cleared alone without render.effects.reflection).
  static void reflection(OceanRenderer& r, const FrameContext& f, const Request&) {
    vk::use(f.cmd, {r.reflection_->color(), r.reflection_->depth()}, Discard, Attachment);
    r.reflection_->record(f, f.scene.render.effects.reflection);
    vk::use(f.cmd, {r.reflection_->color()}, Attachment, Sampled);
  }
  // Reads refraction, reflection, caustics. Writes: the picture above the water (surface and objects).
  static void surface(OceanRenderer& r, const FrameContext& f, const Request& q) {
    vk::use(f.cmd, {q.color, q.depth}, Discard, Attachment);
    r.surface_->record(f,
                       {r.refraction_->albedo_image(), r.refraction_->depth_image(),
                        r.reflection_->color_image(), r.caustics_->map()},
                       q.color, q.depth);
  }
  // Writes: the sky where nothing else was drawn.
  static void sky(OceanRenderer& r, const FrameContext& f, const Request& q) {
    vk::use(f.cmd, {q.color, q.depth}, Attachment, Attachment);
    r.sky_->record(f, q.color, q.depth);
  }
  // Reads refraction, caustics, window. Writes: the view under the water for the part of the lens in it.
  static void underwater_at_waterline(OceanRenderer& r, const FrameContext& f, const Request&) {
    const vk::Target color = r.waterline_->below_color(), depth = r.waterline_->below_depth();
    vk::use(f.cmd, {color, depth}, Discard, Attachment);
    r.underwater_->record(f, below(r), color, depth);
    vk::use(f.cmd, {color, depth}, Attachment, Attachment);
    r.particles_->record(f, color, depth);
    vk::use(f.cmd, {color, depth}, Attachment, Sampled);
  }
  // Reads the view under the water. Writes: the picture where the lens is in the water, and the line.
  static void waterline(OceanRenderer& r, const FrameContext& f, const Request& q) {
    vk::use(f.cmd, {q.color, q.depth}, Attachment, Attachment);
    r.waterline_->record(f, q.color, q.depth);
  }
  // Writes: the surface's ground truth (normal and foam, world point) into the request's float targets.
  static void surface_truth(OceanRenderer& r, const FrameContext& f, const Request& q) {
    q.floats->begin(f.cmd);
    r.surface_->record_aov(f, q.floats->color(0), q.floats->color(1), q.floats->depth());
  }
  // Writes: every mesh's and the floor's ground truth over the surface's, nearest first (when asked).
  static void objects_truth(OceanRenderer& r, const FrameContext& f, const Request& q) {
    if (!q.objects) return;
    const vk::Target normal = q.floats->color(0), world = q.floats->color(1), depth = q.floats->depth();
    vk::use(f.cmd, {normal, world, depth}, Attachment, Attachment);
    vk::begin_rendering(f.cmd, f.extent, {{.view = normal.view}, {.view = world.view}},
                        vk::DepthTarget{.view = depth.view, .clear = std::nullopt});
    r.objects_->draw_ground_truth(f);
    vk::end_rendering(f.cmd);
  }
  // Reads refraction, caustics. Writes: the underwater view's image formation terms.
  static void underwater_terms(OceanRenderer& r, const FrameContext& f, const Request& q) {
    q.floats->begin(f.cmd);
    r.underwater_->record_terms(f, below(r), {q.floats->color(0), q.floats->color(1), q.floats->color(2)},
                                q.floats->depth());
  }

  struct Step {
    const char* pass;
    uint8_t kinds;  // the frames it joins (FrameKind bits)
    uint8_t sides;  // the camera sides it runs for (bit 1 << CameraSide)
    void (*record)(OceanRenderer&, const FrameContext&, const Request&);
  };
  // In recording order.
  static constexpr Step kFrame[] = {
      {"ocean step, wakes", kEveryKind, kEverySide, time_steps},
      {"caustics", kinds({Kind::Picture, Kind::UnderwaterTerms}), kEverySide, caustics},
      {"refraction", kinds({Kind::Picture, Kind::UnderwaterTerms}), kEverySide, refraction},
      // The terms bind the window's image but do not read it (they leave the surface out).
      {"snell window", kinds({Kind::Picture}), kInWater, window},
      {"underwater", kinds({Kind::Picture}), sides({CameraSide::Below}), underwater},
      {"particles", kinds({Kind::Picture}), sides({CameraSide::Below}), particles},
      {"reflection", kinds({Kind::Picture}), kSeesSurface, reflection},
      {"surface", kinds({Kind::Picture}), kSeesSurface, surface},
      {"sky", kinds({Kind::Picture}), kSeesSurface, sky},
      {"underwater at the waterline", kinds({Kind::Picture}), sides({CameraSide::Waterline}),
       underwater_at_waterline},
      {"waterline", kinds({Kind::Picture}), sides({CameraSide::Waterline}), waterline},
      {"surface ground truth", kinds({Kind::SurfaceAov}), kEverySide, surface_truth},
      {"objects ground truth", kinds({Kind::SurfaceAov}), kEverySide, objects_truth},
      {"underwater terms", kinds({Kind::UnderwaterTerms}), kEverySide, underwater_terms},
  };
  // Advancing draws nothing: only the steps of every kind join it.
  static constexpr bool advance_draws_nothing() {
    for (const Step& step : kFrame)
      if ((step.kinds & uint8_t(Kind::Advance)) && step.kinds != kEveryKind) return false;
    return true;
  }
};
static_assert(FrameSteps::advance_draws_nothing());

void OceanRenderer::record_frame(const FrameContext& frame, const FrameRequest& request) {
  const uint8_t side = uint8_t(1u << unsigned(frame.camera_side));
  for (const FrameSteps::Step& step : FrameSteps::kFrame)
    if ((step.kinds & uint8_t(request.kind)) && (step.sides & side)) step.record(*this, frame, request);
}

}  // namespace lagoon::render
