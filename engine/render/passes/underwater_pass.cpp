#include "render/passes/underwater_pass.h"

#include "lagoon_shaders/shaders.h"
#include "render/surface_fields.h"
#include "shared/sediment.h"
#include "shared/surface.h"
#include "vk/rendering.h"

namespace lagoon::render {

UnderwaterPass::UnderwaterPass(vk::Context& ctx, const SurfaceFields& fields, const WaterLuts& luts,
                               const Samplers& samplers, VkFormat color_format, VkFormat depth_format)
    : fields_(fields),
      luts_(luts),
      samplers_(samplers),
      ctx_(ctx),
      depth_format_(depth_format),
      sediment_(fields.sediment) {
  for (uint32_t shafts = 0; shafts < 2; ++shafts) {
    const std::vector<vk::SpecConstant> spec{{LAGOON_UNDERWATER_SPEC_SHAFTS, shafts}};
    // Every pixel, writing the depth of what it shows (the far plane where it shows only water).
    for (uint32_t lamps = 0; lamps < 2; ++lamps)
      medium_[shafts][lamps] = vk::GraphicsPipeline::create(
          ctx, {.vertex = &shaders::render_fullscreen_vert,
                .fragment = &shaders::render_underwater_medium_frag,
                .color_formats = {color_format},
                .depth_format = depth_format,
                .depth_test = true,
                .depth_write = true,
                .depth_compare = VK_COMPARE_OP_ALWAYS,
                .spec = {spec[0],
                         {LAGOON_SURFACE_SPEC_LAMPS, lamps},
                         {LAGOON_SURFACE_SPEC_SEDIMENT, fields.sediment ? 1u : 0u}}});
    // The surface mesh with either winding: from below its triangles face away from the camera.
    surface_[shafts] =
        vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_ocean_surface_vert,
                                           .fragment = &shaders::render_ocean_surface_below_frag,
                                           .color_formats = {color_format},
                                           .depth_format = depth_format,
                                           .depth_test = true,
                                           .depth_write = true,
                                           .spec = with_surface_field_specs({spec[0]}, fields)});
  }
}

std::vector<vk::Binding> UnderwaterPass::table_bindings(const FrameContext& frame) const {
  return {vk::bind(LAGOON_SURFACE_BIND_FRAME, frame.uniforms()),
          vk::bind(LAGOON_SURFACE_BIND_UW_TARGET, sampled(luts_.uw_target, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_UW_DOWN, sampled(luts_.uw_down, samplers_.clamp)),
          vk::bind(LAGOON_SURFACE_BIND_UW_UP, sampled(luts_.uw_up, samplers_.clamp))};
}

std::vector<vk::Binding> UnderwaterPass::medium_bindings(const FrameContext& frame, const Inputs& in) const {
  std::vector<vk::Binding> medium = table_bindings(frame);
  medium.push_back(
      vk::bind(LAGOON_SURFACE_BIND_REFRACTION_ALBEDO, sampled(in.refraction_albedo, samplers_.nearest)));
  medium.push_back(
      vk::bind(LAGOON_SURFACE_BIND_REFRACTION_DEPTH, sampled(in.refraction_depth, samplers_.nearest)));
  medium.push_back(vk::bind(LAGOON_SURFACE_BIND_CAUSTICS, sampled(in.caustics, samplers_.clamp)));
  medium.push_back(vk::bind(LAGOON_SURFACE_BIND_LIGHTS, frame.slot.lights));
  medium.push_back(vk::bind(LAGOON_SURFACE_BIND_SEDIMENT, frame.slot.sediment));
  return medium;
}

void UnderwaterPass::record_terms(const FrameContext& frame, const Inputs& in,
                                  const std::array<vk::Target, 3>& terms, vk::Target depth) {
  const size_t shafts = frame.scene.render.effects.shafts ? 1 : 0, lamps = frame.light_count > 0 ? 1 : 0;
  vk::GraphicsPipeline& pipeline = terms_[shafts][lamps];
  if (pipeline.empty())
    pipeline =
        vk::GraphicsPipeline::create(ctx_, {.vertex = &shaders::render_fullscreen_vert,
                                            .fragment = &shaders::render_underwater_terms_frag,
                                            .color_formats = {kTermsFormat, kTermsFormat, kTermsFormat},
                                            .depth_format = depth_format_,
                                            .depth_test = true,
                                            .depth_write = true,
                                            .depth_compare = VK_COMPARE_OP_ALWAYS,
                                            .spec = {{LAGOON_UNDERWATER_SPEC_SHAFTS, uint32_t(shafts)},
                                                     {LAGOON_SURFACE_SPEC_LAMPS, uint32_t(lamps)},
                                                     {LAGOON_SURFACE_SPEC_SEDIMENT, sediment_ ? 1u : 0u}}});
  const std::array<float, 4> zero{0.f, 0.f, 0.f, 0.f};
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = terms[0].view, .clear = zero},
                       {.view = terms[1].view, .clear = zero},
                       {.view = terms[2].view, .clear = zero}},
                      vk::DepthTarget{.view = depth.view, .clear = 1.0f});
  vk::draw(frame.cmd, pipeline, medium_bindings(frame, in), nullptr, 0, 3);
  vk::end_rendering(frame.cmd);
}

void UnderwaterPass::record(const FrameContext& frame, const Inputs& in, vk::Target color,
                            vk::Target depth) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "underwater");
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = color.view, .clear = std::array{0.f, 0.f, 0.f, 1.f}}},
                      vk::DepthTarget{.view = depth.view, .clear = 1.0f});
  const std::vector<vk::Binding> medium = medium_bindings(frame, in);
  const size_t shafts = frame.scene.render.effects.shafts ? 1 : 0;
  vk::draw(frame.cmd, medium_[shafts][frame.light_count > 0 ? 1 : 0], medium, nullptr, 0, 3);
  std::vector<vk::Binding> surface = table_bindings(frame);
  surface.push_back(vk::bind(LAGOON_SURFACE_BIND_CAUSTICS, sampled(in.caustics, samplers_.clamp)));
  surface.push_back(vk::bind(LAGOON_SURFACE_BIND_WINDOW, sampled(in.window, samplers_.clamp)));
  surface.push_back(vk::bind(LAGOON_SURFACE_BIND_SEDIMENT, frame.slot.sediment));
  for (vk::Binding& b : surface_field_bindings(fields_, samplers_)) surface.push_back(b);
  vk::draw_indexed(frame.cmd, surface_[shafts], surface, frame.slot.surface_indices.handle(),
                   frame.slot.surface_index_count);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
