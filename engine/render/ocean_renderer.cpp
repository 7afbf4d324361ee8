#include "render/ocean_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gltf/gltf_loader.h"
#include "lagoon_shaders/shaders.h"
#include "ocean/slope_statistics.h"
#include "optics/colour.h"
#include "optics/lut.h"
#include "render/camera.h"
#include "render/seafloor.h"
#include "render/surface_grid.h"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include "shared/frame.h"
#include "shared/mesh.h"
#include "vk/barriers.h"
#include "vk/rendering.h"
#include "vk/sampler.h"
#include "vk/transfer.h"

namespace lagoon::render {
namespace {

constexpr float kFoamAlbedo = 0.85f;
constexpr double kSunDiscRadiusRad = 0.00465;

// The same shape as common/light.glsl's sky_shape; integrated here so the sky's E_sky is the model's.
double sky_shape(glm::dvec3 dir, glm::dvec3 sun) {
  const double up = std::max(dir.y, 0.0), horizon = 1.0 - up;
  return 0.55 + 1.2 * std::pow(horizon, 4) + 0.6 * std::pow(std::max(glm::dot(dir, sun), 0.0), 12.0);
}

// (1/π) ∫ shape(ω) cos θ dω over the upper hemisphere: a uniform shape of 1 gives 1.
double sky_shape_integral(glm::dvec3 sun) {
  const int steps_theta = 64, steps_phi = 128;
  double sum = 0;
  for (int i = 0; i < steps_theta; ++i) {
    const double theta = (i + 0.5) * (M_PI / 2) / steps_theta;
    for (int j = 0; j < steps_phi; ++j) {
      const double phi = (j + 0.5) * 2 * M_PI / steps_phi;
      const glm::dvec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      sum += sky_shape(dir, sun) * std::cos(theta) * std::sin(theta);
    }
  }
  return sum * (M_PI / 2 / steps_theta) * (2 * M_PI / steps_phi) / M_PI;
}

vk::ImageRef sampled(const vk::Image& image, VkSampler sampler) {
  return {image.view(), VK_IMAGE_LAYOUT_GENERAL, sampler};
}

}  // namespace

OceanRenderer::OceanRenderer(vk::Context& ctx, const scene::Scene& scene)
    : ctx_(ctx),
      ocean_(std::make_unique<ocean::GpuOcean>(ctx, scene.ocean)),
      // At the far plane (fullscreen.vert's z = 1), drawn where the depth buffer is still clear.
      sky_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_fullscreen_vert,
                                              .fragment = &shaders::render_sky_frag,
                                              .color_formats = {kColorFormat},
                                              .depth_format = kDepthFormat,
                                              .depth_test = true,
                                              .depth_write = false,
                                              .depth_compare = VK_COMPARE_OP_EQUAL})),
      // The surface pass writes display-referred colour: each of its shaders tone-maps its own output
      // (common/tonemap.glsl), so there is no HDR frame and no full-screen post pass.
      surface_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_ocean_surface_vert,
                                                  .fragment = &shaders::render_ocean_surface_frag,
                                                  .color_formats = {kColorFormat},
                                                  .depth_format = kDepthFormat,
                                                  .depth_test = true,
                                                  .depth_write = true})),
      // Anisotropic filtering is cheap in GPU hardware but runs in software on CPU devices.
      repeat_sampler_(vk::create_sampler(
          ctx, {.address = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                .max_anisotropy = ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1.0f : 8.0f})),
      clamp_sampler_(vk::create_sampler(ctx, {.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE})),
      nearest_sampler_(vk::create_sampler(ctx, {.filter = VK_FILTER_NEAREST,
                                                .mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                                .address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE})) {
  for (Slot& slot : slots_) {
    slot.frame = vk::Buffer::create(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                    vk::MemoryUsage::Upload, "frame");
    slot.lights =
        vk::Buffer::create(ctx, sizeof(gpu::PointLightGpu) * kMaxLights, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                           vk::MemoryUsage::Upload, "point lights");
    slot.timer = vk::GpuTimer(ctx, 32);
    slot.surface_indices =
        vk::Buffer::create(ctx, kClipmapMaxIndices * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                           vk::MemoryUsage::Upload, "surface indices");
  }
  for (auto [pipeline, format] : {std::pair{&mesh_hdr_, kHdrFormat}, {&mesh_display_, kColorFormat}})
    *pipeline = vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_mesh_vert,
                                                   .fragment = &shaders::render_mesh_frag,
                                                   .color_formats = {format},
                                                   .depth_format = kDepthFormat,
                                                   .depth_test = true,
                                                   .depth_write = true});
}

Result<std::unique_ptr<OceanRenderer>> OceanRenderer::create(vk::Context& ctx, const scene::Scene& scene) {
  std::unique_ptr<OceanRenderer> renderer(new OceanRenderer(ctx, scene));
  if (auto r = renderer->init(scene); !r) return r.error();
  return renderer;
}

Result<void> OceanRenderer::init(const scene::Scene& scene) {
  // The glint's width (ocean_surface.frag): each drawn cascade's mean square slope, and that of the waves
  // shorter than the last drawn cascade. Fixed with the ocean, so computed once here.
  const uint32_t drawn = std::min(ocean_->cascade_count(), 4u);
  double variance = 0;
  for (uint32_t c = 0; c < drawn; ++c) {
    cascade_mss_[c] = float(ocean::mean_square_slope(ocean_->spectra()[c]));
    variance += ocean::height_variance(ocean_->spectra()[c]);
  }
  // Blocks of the surface mesh are culled against the view with 6σ of the displacement (plus a metre).
  const double sigma = std::sqrt(variance);
  displacement_bound_ = {.horizontal_m = float(6.0 * sigma * ocean_->params().choppiness + 1.0),
                         .vertical_m = float(6.0 * sigma + 1.0)};
  const double last_k = ocean::cascade_bands(ocean_->params())[drawn - 1].k_max;
  subgrid_mss_ = float(ocean::spectrum_mean_square_slope(ocean_->params(), last_k, ocean::kCapillaryCutoffK));

  // The colour LUTs of the scene's water under its sun, as textures (docs/optics.md).
  auto inputs = optics::lut_inputs(scene.water, scene.sun.elevation_deg);
  if (!inputs) return inputs.error();
  auto lut = optics::build_water_lut(*inputs);
  if (!lut) return lut.error();
  deep_colour_ = glm::vec3(lut->deep_colour);
  lut_r_max_ = scene.water.lut_r_max_m;
  lut_h_max_ = scene.water.lut_h_max_m;
  const uint32_t rn = lut->r_count, hn = lut->h_count;
  std::vector<float> t0(size_t{rn} * hn * 4), t1(size_t{rn} * hn * 4);
  for (uint32_t j = 0; j < hn; ++j)
    for (uint32_t i = 0; i < rn; ++i) {
      const size_t texel = (size_t{j} * rn + i) * 4,
                   src = size_t{i} * hn + j;  // LUT is [r][h]; image rows are h
      for (int c = 0; c < 4; ++c) t0[texel + c] = lut->t0[src * 4 + c];
      for (int c = 0; c < 3; ++c) t1[texel + c] = lut->t1[src * 3 + c];
      t1[texel + 3] = 1.0f;
    }
  for (auto [image, data, name] : {std::tuple{&lut_t0_, &t0, "lut T0"}, {&lut_t1_, &t1, "lut T1"}}) {
    *image = vk::Image::create(ctx_, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                      .extent = {rn, hn},
                                      .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                      .debug_name = name});
    vk::upload_image(ctx_, *image, vk::as_bytes_of(*data), VK_IMAGE_LAYOUT_GENERAL,
                     vk::access::kGraphicsSampled);
  }
  const io::Image8 white{.width = 1, .height = 1, .rgba = {255, 255, 255, 255}};
  white_texture_ = upload_texture(ctx_, white, "white");

  const scene::Seafloor& floor = scene.seafloor;
  if (floor.type == "slope") {
    const FloorMesh mesh =
        build_slope_floor(floor, glm::vec2(scene.camera.position.x, scene.camera.position.z));
    floor_ = upload_mesh(ctx_, mesh.vertices, mesh.indices);
    floor_albedo_ = floor.albedo;
    floor_texture_scale_ = floor.texture_scale_m;
    if (!floor.texture.empty()) {
      auto image = io::read_png(floor.texture);
      if (!image) return make_error("seafloor.texture: " + image.error().message);
      floor_texture_ = upload_texture(ctx_, *image, "floor texture");
      floor_textured_ = true;
    }
  }
  return load_objects(scene);
}

Result<void> OceanRenderer::load_model(const std::string& file, const glm::mat4& transform,
                                       const std::string& field) {
  auto model = gltf::load_gltf(file);
  if (!model) return make_error(field + ": " + model.error().message);
  for (const std::string& warning : model->warnings)
    std::fprintf(stderr, "lagoon: warning: %s: %s\n", file.c_str(), warning.c_str());
  const int texture_base = int(textures_.size());
  for (const gltf::Texture& t : model->textures)
    textures_.push_back(upload_texture(ctx_, io::Image8{.width = t.width, .height = t.height, .rgba = t.rgba},
                                       "model texture"));
  for (const gltf::Instance& instance : model->instances) {
    for (const gltf::Primitive& p : model->meshes[instance.mesh].primitives) {
      std::vector<MeshVertex> vertices(p.positions.size());
      for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {p.positions[i], p.normals[i], i < p.uvs.size() ? p.uvs[i] : glm::vec2(0)};
      ObjectDraw draw{.mesh = upload_mesh(ctx_, vertices, p.indices), .world = transform * instance.world};
      if (p.material >= 0) {
        const gltf::Material& m = model->materials[p.material];
        draw.base_colour = glm::vec4(glm::vec3(m.base_color_factor), m.base_color_texture >= 0 ? 1.0f : 0.0f);
        if (m.base_color_texture >= 0) draw.texture = texture_base + m.base_color_texture;
      }
      objects_.push_back(std::move(draw));
    }
  }
  return {};
}

Result<void> OceanRenderer::load_objects(const scene::Scene& scene) {
  // A glTF sea floor is drawn like an object: the passes clip it at the water line like everything else.
  if (scene.seafloor.type == "gltf")
    if (auto r = load_model(scene.seafloor.file, glm::mat4(1.0f), "seafloor.file"); !r) return r;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const scene::Object& object = scene.objects[o];
    // T(position) · Ry(yaw) · Rx(−pitch) · Rz(roll) · S(scale) (docs/scene-format.md, Objects).
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), object.position);
    transform = glm::rotate(transform, glm::radians(object.rotation_deg.x), glm::vec3(0, 1, 0));
    transform = glm::rotate(transform, glm::radians(-object.rotation_deg.y), glm::vec3(1, 0, 0));
    transform = glm::rotate(transform, glm::radians(object.rotation_deg.z), glm::vec3(0, 0, 1));
    transform = glm::scale(transform, glm::vec3(object.scale));
    if (auto r = load_model(object.file, transform, "objects[" + std::to_string(o) + "].file"); !r) return r;
  }
  return {};
}

void OceanRenderer::draw_objects(VkCommandBuffer cmd, float mode) const {
  const vk::BufferRef frame{slots_[slot_].frame.handle()};
  // Mode 0 draws into the display-referred frame (mesh.frag tone-maps it), the others into HDR targets.
  const vk::GraphicsPipeline& pipeline = mode < 0.5f ? mesh_display_ : mesh_hdr_;
  for (const ObjectDraw& o : objects_) {
    const gpu::MeshPush push{
        .model = o.world, .base_colour = o.base_colour, .params = glm::vec4(mode, 0, 0, 0)};
    const vk::Image& texture = o.texture >= 0 ? textures_[o.texture] : white_texture_;
    vk::draw(cmd, pipeline,
             {vk::bind(0, frame), vk::bind(1, o.mesh.vertices), vk::bind(2, o.mesh.indices),
              vk::bind(3, sampled(texture, repeat_sampler_)), vk::bind(4, slots_[slot_].lights)},
             push, o.mesh.index_count);
  }
}

OceanRenderer::~OceanRenderer() = default;

struct OceanRenderer::Targets {
  vk::Image depth, color, refraction_albedo, refraction_depth, reflection, reflection_depth;
  vk::Buffer readback;  // the tone-mapped colour, copied in the frame's own submit
};

const OceanRenderer::Targets& OceanRenderer::targets_for(VkExtent2D extent) {
  if (targets_ && targets_->color.extent().width == extent.width &&
      targets_->color.extent().height == extent.height)
    return *targets_;
  if (targets_) ctx_.wait_idle();  // frames in flight may still use the old size
  targets_.reset();                // free the old size first: the new one may be large
  const VkImageUsageFlags attachment = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  const VkImageUsageFlags depth_attachment =
      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  auto target = [&](VkFormat format, VkImageUsageFlags usage, const char* name) {
    return vk::Image::create(ctx_, {.format = format, .extent = extent, .usage = usage, .debug_name = name});
  };
  vk::Image color =
      target(kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "color");
  vk::Buffer readback = vk::Buffer::create(ctx_, vk::readback_bytes(color), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           vk::MemoryUsage::Readback, "frame readback");
  targets_ = std::make_unique<Targets>(
      Targets{.depth = target(kDepthFormat, depth_attachment, "depth"),
              .color = std::move(color),
              .refraction_albedo = target(kHdrFormat, attachment, "refraction albedo"),
              .refraction_depth = target(kDepthFormat, depth_attachment, "refraction depth"),
              .reflection = target(kHdrFormat, attachment, "reflection"),
              .reflection_depth = target(kDepthFormat, depth_attachment, "reflection depth"),
              .readback = std::move(readback)});
  return *targets_;
}

void OceanRenderer::record_frame(VkCommandBuffer cmd, const Targets& t) {
  const vk::Image &depth = t.depth, &color = t.color;
  const VkExtent2D extent = color.extent();
  const vk::BufferRef frame{slots_[slot_].frame.handle()};
  {
    vk::GpuScope scope(slots_[slot_].timer, cmd, "refraction");
    for (const vk::Image* image : {&t.refraction_albedo})
      vk::image_barrier(cmd, image->handle(), image->all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kNone,
                        vk::access::kColorAttachmentWrite);
    vk::image_barrier(cmd, t.refraction_depth.handle(), t.refraction_depth.all_subresources(),
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kDepthAttachment);
    vk::begin_rendering(cmd, extent,
                        {{.view = t.refraction_albedo.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                        vk::DepthTarget{.view = t.refraction_depth.view(), .clear = 1.0f});
    if (floor_) {
      const gpu::MeshPush push{.model = glm::mat4(1.0f),
                               .base_colour = glm::vec4(floor_albedo_, floor_textured_ ? 1.0f : 0.0f),
                               .params = glm::vec4(1.0f, floor_texture_scale_, 0.0f, 0.0f)};
      const vk::Image& texture = floor_textured_ ? floor_texture_ : white_texture_;
      vk::draw(cmd, mesh_hdr_,
               {vk::bind(0, frame), vk::bind(1, floor_->vertices), vk::bind(2, floor_->indices),
                vk::bind(3, sampled(texture, repeat_sampler_)), vk::bind(4, slots_[slot_].lights)},
               push, floor_->index_count);
    }
    draw_objects(cmd, 1.0f);  // their submerged parts
    vk::end_rendering(cmd);
    vk::image_barrier(cmd, t.refraction_albedo.handle(), t.refraction_albedo.all_subresources(),
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      vk::access::kColorAttachmentWrite, vk::access::kGraphicsSampled);
    vk::image_barrier(cmd, t.refraction_depth.handle(), t.refraction_depth.all_subresources(),
                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      vk::access::kDepthAttachment, vk::access::kGraphicsSampled);
  }
  {
    // Planar reflection: what is above the water, mirrored about the mean water level, seen by the main
    // camera. Alpha marks where something was drawn; elsewhere the surface reflects the analytic sky.
    vk::GpuScope scope(slots_[slot_].timer, cmd, "reflection");
    vk::image_barrier(cmd, t.reflection.handle(), t.reflection.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kColorAttachmentWrite);
    vk::image_barrier(cmd, t.reflection_depth.handle(), t.reflection_depth.all_subresources(),
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kDepthAttachment);
    vk::begin_rendering(cmd, extent, {{.view = t.reflection.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                        vk::DepthTarget{.view = t.reflection_depth.view(), .clear = 1.0f});
    if (reflection_on_) draw_objects(cmd, 2.0f);
    vk::end_rendering(cmd);
    vk::image_barrier(cmd, t.reflection.handle(), t.reflection.all_subresources(),
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      vk::access::kColorAttachmentWrite, vk::access::kGraphicsSampled);
  }
  std::vector<vk::Binding> surface_bindings{vk::bind(7, sampled(t.reflection, clamp_sampler_)),
                                            vk::bind(0, frame),
                                            vk::bind(3, sampled(t.refraction_albedo, clamp_sampler_)),
                                            vk::bind(4, sampled(t.refraction_depth, nearest_sampler_)),
                                            vk::bind(5, sampled(lut_t0_, clamp_sampler_)),
                                            vk::bind(6, sampled(lut_t1_, clamp_sampler_)),
                                            vk::bind(8, slots_[slot_].lights)};
  for (vk::Binding& b : cascade_bindings()) surface_bindings.push_back(b);
  vk::image_barrier(cmd, color.handle(), color.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kNone,
                    vk::access::kColorAttachmentWrite);
  vk::image_barrier(cmd, depth.handle(), depth.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kNone,
                    vk::access::kDepthAttachment);
  {
    // Separate render passes so the timestamps bracket real work on tilers such as lavapipe.
    vk::GpuScope scope(slots_[slot_].timer, cmd, "surface");
    vk::begin_rendering(cmd, extent, {{.view = color.view(), .clear = std::array{0.f, 0.f, 0.f, 1.f}}},
                        vk::DepthTarget{.view = depth.view(), .clear = 1.0f});
    draw_objects(cmd, 0.0f);  // above-water parts, lit; the surface depth-tests against them
    vk::draw_indexed(cmd, surface_, surface_bindings, slots_[slot_].surface_indices.handle(),
                     surface_indices_);
    vk::end_rendering(cmd);
  }
  // The sky last, at the far plane and depth-tested: it is shaded only where nothing else was drawn.
  vk::image_barrier(cmd, color.handle(), color.all_subresources(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kColorAttachmentWrite,
                    vk::access::kColorAttachmentWrite);
  vk::image_barrier(cmd, depth.handle(), depth.all_subresources(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kDepthAttachment,
                    vk::access::kDepthAttachment);
  {
    vk::GpuScope scope(slots_[slot_].timer, cmd, "sky");
    vk::begin_rendering(cmd, extent, {{.view = color.view()}},
                        vk::DepthTarget{.view = depth.view(), .clear = {}});
    vk::draw(cmd, sky_, {vk::bind(0, frame)}, 3);
    vk::end_rendering(cmd);
  }
}

std::vector<vk::Binding> OceanRenderer::cascade_bindings() const {
  std::vector<vk::Binding> bindings;
  for (uint32_t slot = 0; slot < 4; ++slot) {
    const ocean::CascadeTextures t = ocean_->cascade(std::min(slot, ocean_->cascade_count() - 1));
    bindings.push_back(vk::bind(1, sampled(*t.displacement, repeat_sampler_), slot));
    bindings.push_back(vk::bind(9, sampled(*t.jacobian_terms, repeat_sampler_), slot));
    bindings.push_back(vk::bind(2, sampled(*t.normal_jacobian, repeat_sampler_), slot));
  }
  return bindings;
}

const vk::Image& OceanRenderer::record(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent,
                                       uint32_t slot) {
  prepare_frame(cmd, scene, extent, slot);
  const Targets& targets = targets_for(extent);
  record_frame(cmd, targets);
  return targets.color;
}

void OceanRenderer::prepare_frame(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent,
                                  uint32_t slot) {
  slot_ = slot % kSlots;
  Slot& frame_slot = slots_[slot_];
  const double t = scene.time_s;
  // A still frame needs the foam a running ocean would have: run the last few seconds first.
  if (ocean_time_ < 0 || t < ocean_time_ || t - ocean_time_ > kWarmupS) {
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
      double previous = t - kWarmupS;
      // The warm-up's textures are not drawn: only the last step (the frame's own) rebuilds the mips.
      ocean_->record_step(cmd, previous, 0.0, nullptr, ocean::GpuOcean::Mips::Skip);
      for (double step = previous + kWarmupStep; step < t - 1e-9; step += kWarmupStep) {
        ocean_->record_step(cmd, step, step - previous, nullptr, ocean::GpuOcean::Mips::Skip);
        previous = step;
      }
      ocean_time_ = previous;
    });
  }

  reflection_on_ = scene.render.effects.reflection;
  const uint32_t light_count = uint32_t(std::min<size_t>(scene.lights.size(), kMaxLights));
  auto* lights = reinterpret_cast<gpu::PointLightGpu*>(frame_slot.lights.mapped());
  for (uint32_t i = 0; i < light_count; ++i) {
    const scene::PointLight& l = scene.lights[i];
    lights[i] = {.position_range = glm::vec4(l.position, l.range_m),
                 .colour = glm::vec4(l.colour * l.intensity, 0)};
  }
  frame_slot.lights.flush();
  const SkyLight light = sky_light(scene.sun);
  const CameraMatrices cam = camera_matrices(scene.camera, float(extent.width) / float(extent.height));
  const optics::ToneMapCurve curve = optics::tone_map_curve();
  const float reach = std::min(0.8f * scene.camera.far_m, 3000.0f);
  const SurfaceGrid grid = surface_grid(scene.camera.position, reach, &cam.view_proj, displacement_bound_);
  surface_indices_ = uint32_t(grid.indices.size());
  std::memcpy(frame_slot.surface_indices.mapped(), grid.indices.data(),
              grid.indices.size() * sizeof(uint32_t));
  frame_slot.surface_indices.flush();
  gpu::FrameUniforms f{
      .view_proj = cam.view_proj,
      .inv_view_proj = glm::inverse(cam.view_proj),
      .camera_pos = glm::vec4(scene.camera.position, float(t)),
      .sun_dir = glm::vec4(light.sun_direction, float(scene.water.ior)),
      .sun_irradiance =
          glm::vec4(light.sun_irradiance, float(1.0 / sky_shape_integral(glm::dvec3(light.sun_direction)))),
      .sky_radiance = glm::vec4(light.sky_radiance, float(std::cos(kSunDiscRadiusRad))),
      .sun_disc = glm::vec4(light.sun_disc_radiance, 0.0f),
      .water_deep = glm::vec4(deep_colour_, kFoamAlbedo),
      .grid =
          glm::vec4(grid.grid.x, grid.grid.y, 0.35f * reach, float(std::min(ocean_->cascade_count(), 4u))),
      .clipmap = grid.clipmap,
      .cascade_mss = cascade_mss_,
      .glint = glm::vec4(subgrid_mss_, float(ocean_->params().foam.threshold), 0, 0),
      .post = glm::vec4(scene.render.exposure, scene.render.gamma, float(curve.m), float(curve.exponent)),
      .post2 = glm::vec4(float(curve.white), float(curve.world_adaptation),
                         scene.render.tone_map == "clamp" ? 0.0f : 1.0f, 0.0f),
      .lut = glm::vec4(float(lut_r_max_), float(lut_h_max_), scene.render.effects.refraction ? 1.0f : 0.0f,
                       light.light_scale),
      .screen = glm::vec4(float(extent.width), float(extent.height), 1.0f / float(extent.width),
                          1.0f / float(extent.height)),
      .lights = glm::vec4(float(light_count), 0, 0, 0)};
  for (uint32_t c = 0; c < std::min(ocean_->cascade_count(), 4u); ++c) {
    const ocean::CascadeTextures tex = ocean_->cascade(c);
    f.cascade_patch[c] = float(tex.patch_size_m);
    f.cascade_layer[c] = float(tex.layer);
    f.cascade_texel[c] = float(tex.patch_size_m / tex.resolution);
  }
  std::memcpy(frame_slot.frame.mapped(), &f, sizeof(f));
  frame_slot.frame.flush();

  // Frames may be recorded while the previous one runs; they share the ocean's textures and the render
  // targets, so this frame's work starts after everything submitted before it.
  vk::memory_barrier(cmd, vk::access::kAllCommands, vk::access::kAllCommands);
  frame_slot.timer.reset(cmd);
  ocean_->record_step(cmd, t, t - ocean_time_, &frame_slot.timer);
  ocean_time_ = t;
}

OceanRenderer::SurfaceAov OceanRenderer::render_surface_aov(const scene::Scene& scene) {
  constexpr VkFormat kAovFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  if (surface_aov_.pipeline() == VK_NULL_HANDLE)
    surface_aov_ = vk::GraphicsPipeline::create(ctx_, {.vertex = &shaders::render_ocean_surface_vert,
                                                       .fragment = &shaders::render_ocean_surface_aov_frag,
                                                       .color_formats = {kAovFormat, kAovFormat},
                                                       .depth_format = kDepthFormat,
                                                       .depth_test = true,
                                                       .depth_write = true});
  const VkExtent2D extent{scene.render.width, scene.render.height};
  auto target = [&](VkFormat format, VkImageUsageFlags usage, const char* name) {
    return vk::Image::create(ctx_, {.format = format, .extent = extent, .usage = usage, .debug_name = name});
  };
  const VkImageUsageFlags out = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  const vk::Image normal = target(kAovFormat, out, "aov normal"),
                  world = target(kAovFormat, out, "aov world"),
                  depth = target(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "aov depth");
  auto staging = [&](const vk::Image& image) {
    return vk::Buffer::create(ctx_, vk::readback_bytes(image), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::Readback, "aov readback");
  };
  const vk::Buffer normal_out = staging(normal), world_out = staging(world);
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    prepare_frame(cmd, scene, extent, 0);
    for (const vk::Image* image : {&normal, &world})
      vk::image_barrier(cmd, image->handle(), image->all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kNone,
                        vk::access::kColorAttachmentWrite);
    vk::image_barrier(cmd, depth.handle(), depth.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kDepthAttachment);
    vk::begin_rendering(cmd, extent,
                        {{.view = normal.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}},
                         {.view = world.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                        vk::DepthTarget{.view = depth.view(), .clear = 1.0f});
    std::vector<vk::Binding> bindings = cascade_bindings();
    bindings.push_back(vk::bind(0, vk::BufferRef{slots_[slot_].frame.handle()}));
    vk::draw_indexed(cmd, surface_aov_, bindings, slots_[slot_].surface_indices.handle(), surface_indices_);
    vk::end_rendering(cmd);
    vk::record_readback(cmd, normal, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        vk::access::kColorAttachmentWrite, normal_out);
    vk::record_readback(cmd, world, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        vk::access::kColorAttachmentWrite, world_out);
  });
  SurfaceAov aov{.width = extent.width, .height = extent.height};
  for (auto [buffer, values] : {std::pair{&normal_out, &aov.normal_foam}, {&world_out, &aov.world}}) {
    buffer->invalidate();
    values->resize(size_t{extent.width} * extent.height);
    std::memcpy(values->data(), buffer->mapped(), values->size() * sizeof(glm::vec4));
  }
  return aov;
}

std::vector<vk::PassTime> OceanRenderer::timings(uint32_t slot) const {
  return slots_[slot % kSlots].timer.results();
}

io::Image8 OceanRenderer::render(const scene::Scene& scene, std::vector<vk::PassTime>* timings) {
  const VkExtent2D extent{scene.render.width, scene.render.height};
  const Targets* targets = nullptr;
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    record(cmd, scene, extent, 0);
    targets = targets_.get();
    vk::record_readback(cmd, targets->color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        vk::access::kColorAttachmentWrite, targets->readback);
  });
  if (timings) *timings = this->timings(0);

  targets->readback.invalidate();
  io::Image8 image;
  image.width = extent.width;
  image.height = extent.height;
  image.rgba.resize(vk::readback_bytes(targets->color));
  std::memcpy(image.rgba.data(), targets->readback.mapped(), image.rgba.size());
  return image;
}

}  // namespace lagoon::render
