#include "render/passes/surface_pass.h"

#include <algorithm>

#include "lagoon_shaders/shaders.h"
#include "render/surface_fields.h"
#include "shared/sediment.h"
#include "shared/surface.h"
#include "vk/rendering.h"

namespace lagoon::render {

SurfacePass::SurfacePass(vk::Context& ctx, const SurfaceFields& fields, const SceneObjects& objects,
                         const WaterLuts& luts, const Samplers& samplers, VkFormat color_format,
                         VkFormat depth_format)
    : ctx_(ctx),
      fields_(fields),
      objects_(objects),
      luts_(luts),
      samplers_(samplers),
      color_format_(color_format),
      depth_format_(depth_format) {
  // Writes display-referred colour: each shader tone-maps its own output (common/tonemap.glsl), so there is
  // no HDR frame and no full-screen post pass.
  for (uint32_t v = 0; v < surface_.size(); ++v)
    surface_[v] = vk::GraphicsPipeline::create(
        ctx, {.vertex = &shaders::render_ocean_surface_vert,
              .fragment = &shaders::render_ocean_surface_frag,
              .color_formats = {color_format},
              .depth_format = depth_format,
              .depth_test = true,
              .depth_write = true,
              .spec = with_surface_field_specs({{LAGOON_SURFACE_SPEC_LAMPS, v & 1u},
                                                {LAGOON_SURFACE_SPEC_CAUSTICS, (v >> 1) & 1u},
                                                {LAGOON_SURFACE_SPEC_FIRST_HIT, v >> 2}},
                                               fields)});
}

void SurfacePass::record(const FrameContext& frame, const Inputs& in, vk::Target color,
                         vk::Target depth) const {
  const scene::Shading shading = frame.scene.render.shading;
  std::vector<vk::Binding> bindings = surface_field_bindings(fields_, samplers_);
  bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_FRAME, frame.uniforms()));
  bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_LIGHTS, frame.slot.lights));
  if (shading == scene::Shading::Physical)
    for (const vk::Binding& b :
         {vk::bind(LAGOON_SURFACE_BIND_REFLECTION, sampled(in.reflection, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_REFRACTION_ALBEDO, sampled(in.refraction_albedo, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_REFRACTION_DEPTH, sampled(in.refraction_depth, samplers_.nearest)),
          vk::bind(LAGOON_SURFACE_BIND_LUT_T0, sampled(luts_.t0, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_LUT_T1, sampled(luts_.t1, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_SEDIMENT, frame.slot.sediment),
          vk::bind(LAGOON_SURFACE_BIND_CAUSTICS, sampled(in.caustics, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_UW_TARGET, sampled(luts_.uw_target, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_UW_DOWN, sampled(luts_.uw_down, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_UW_UP, sampled(luts_.uw_up, samplers_.clamp))})
      bindings.push_back(b);
  // Its own render pass, so the timestamps bracket real work on tilers such as lavapipe.
  vk::GpuScope scope(frame.timer(), frame.cmd, "surface");
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = color.view, .clear = std::array{0.f, 0.f, 0.f, 1.f}}},
                      vk::DepthTarget{.view = depth.view, .clear = 1.0f});
  objects_.draw(frame, gpu::MeshMode::Lit);  // above-water parts, lit; the surface depth-tests against them
  const vk::GraphicsPipeline& pipeline =
      shading == scene::Shading::Physical
          ? surface_[(frame.light_count > 0 ? 1u : 0u) | (frame.caustics ? 2u : 0u) |
                     (frame.submerged_objects ? 4u : 0u)]
          : classic(shading);
  vk::draw_indexed(frame.cmd, pipeline, bindings, frame.slot.surface_indices.handle(),
                   frame.slot.surface_index_count);
  vk::end_rendering(frame.cmd);
}

// Built on first use: most scenes never ask for the classic modes.
const vk::GraphicsPipeline& SurfacePass::classic(scene::Shading shading) const {
  const uint32_t mode = uint32_t(shading);  // 1 blinn-phong, 2 gouraud, 3 flat (shared/surface.h)
  vk::GraphicsPipeline& p = classic_[mode - 1];
  if (p.empty())
    p = vk::GraphicsPipeline::create(
        ctx_, {.vertex = &shaders::render_ocean_surface_classic_vert,
               .fragment = &shaders::render_ocean_surface_classic_frag,
               .color_formats = {color_format_},
               .depth_format = depth_format_,
               .depth_test = true,
               .depth_write = true,
               .spec = with_surface_field_specs({{LAGOON_SURFACE_SPEC_SHADING, mode}}, fields_)});
  return p;
}

void SurfacePass::record_aov(const FrameContext& frame, vk::Target normal_foam, vk::Target world,
                             vk::Target depth) {
  if (aov_.empty())
    aov_ = vk::GraphicsPipeline::create(ctx_, {.vertex = &shaders::render_ocean_surface_vert,
                                               .fragment = &shaders::render_ocean_surface_aov_frag,
                                               .color_formats = {kAovFormat, kAovFormat},
                                               .depth_format = depth_format_,
                                               .depth_test = true,
                                               .depth_write = true,
                                               .spec = with_surface_field_specs({}, fields_)});
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = normal_foam.view, .clear = std::array{0.f, 0.f, 0.f, 0.f}},
                       {.view = world.view, .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                      vk::DepthTarget{.view = depth.view, .clear = 1.0f});
  std::vector<vk::Binding> bindings = surface_field_bindings(fields_, samplers_);
  bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_FRAME, frame.uniforms()));
  vk::draw_indexed(frame.cmd, aov_, bindings, frame.slot.surface_indices.handle(),
                   frame.slot.surface_index_count);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
