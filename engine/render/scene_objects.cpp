#include "render/scene_objects.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include <glm/common.hpp>
#include "gltf/gltf_loader.h"
#include "lagoon_shaders/shaders.h"
#include "shared/ground_truth.h"

#include "render/dfg_table.h"
#include "render/mesh_material.h"
#include "render/seafloor.h"
#include "vk/barriers.h"
#include "vk/transfer.h"
#include "world/object_pose.h"

namespace lagoon::render {
namespace {

// Lowest and highest world y of a box's corners under `world` (a bound of what it holds).
glm::vec2 world_y_range(const glm::mat4& world, glm::vec3 lo, glm::vec3 hi) {
  glm::vec2 range(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    const float y = (world * glm::vec4(corner, 1.0f)).y;
    range = glm::vec2(std::min(range.x, y), std::max(range.y, y));
  }
  return range;
}

}  // namespace

SceneObjects::SceneObjects(vk::Context& ctx, const Samplers& samplers)
    : ctx_(ctx),
      samplers_(samplers),
      environment_sampler_(vk::create_sampler(ctx, {.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                                    .address = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                                    .address_v = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                                    .mip_levels = false})),
      environment_(ctx) {}

Result<std::unique_ptr<SceneObjects>> SceneObjects::load(vk::Context& ctx, const scene::Scene& scene,
                                                         const Samplers& samplers, VkFormat display_format,
                                                         VkFormat hdr_format, VkFormat depth_format) {
  std::unique_ptr<SceneObjects> objects(new SceneObjects(ctx, samplers));
  static_assert(LAGOON_MESH_WINDOW + 1 == std::tuple_size_v<decltype(pipelines_)>, "a pipeline per mode");
  for (uint32_t mode = 0; mode < objects->pipelines_.size(); ++mode) {
    for (bool blend : {false, true}) {
      (blend ? objects->blend_pipelines_ : objects->pipelines_)[mode] = vk::GraphicsPipeline::create(
          ctx, {.vertex = &shaders::render_mesh_vert,
                .fragment = &shaders::render_mesh_frag,
                .color_formats = {mode == LAGOON_MESH_LIT ? display_format : hdr_format},
                .depth_format = depth_format,
                .depth_test = true,
                .depth_write = !blend,
                .alpha_blend = blend,
                .spec = {{LAGOON_MESH_SPEC_MODE, mode}}});
    }
  }
  const io::Image8 white{.width = 1, .height = 1, .rgba = {255, 255, 255, 255}};
  objects->white_texture_ = upload_texture(ctx, white, "white");
  objects->materials_.push_back(default_material_gpu());  // materials_[0]: primitives without a material
  objects->dfg_texture_ =
      vk::Image::create(ctx, {.format = VK_FORMAT_R32G32_SFLOAT,
                              .extent = {LAGOON_DFG_SIZE, LAGOON_DFG_SIZE},
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .debug_name = "dfg table"});
  vk::upload_image(ctx, objects->dfg_texture_, std::as_bytes(std::span(dfg_table().ab)),
                   VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled);
  if (auto r = objects->load_floor(scene); !r) return r.error();
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const std::string field = "objects[" + std::to_string(o) + "].file";
    const size_t first = objects->objects_.size();
    objects->object_world_.push_back(world::object_transform(scene.objects[o]));
    const std::optional<size_t> lights_of =
        scene.objects[o].lights_from_gltf ? std::optional(o) : std::nullopt;
    if (auto r = objects->load_model(scene.objects[o].file, world::object_transform(scene.objects[o]), field,
                                     lights_of);
        !r)
      return r.error();
    objects->object_draws_.push_back({first, objects->objects_.size()});
  }
  // Vehicles follow the objects (object index objects.size() + v); their pose is set every frame.
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    const scene::Vehicle& vehicle = scene.vehicles[v];
    const std::string field = "vehicles[" + std::to_string(v) + "].file";
    const size_t first = objects->objects_.size();
    const glm::vec2 start = vehicle.path.waypoints.empty() ? glm::vec2(0.0f) : vehicle.path.waypoints.front();
    const glm::mat4 at = world::object_transform(glm::dvec3(start.x, -vehicle.depth_m, start.y),
                                                 glm::dquat(1, 0, 0, 0), vehicle.scale);
    const size_t object = scene.objects.size() + v;
    objects->object_world_.push_back(at);
    const std::optional<size_t> lights_of = vehicle.lights_from_gltf ? std::optional(object) : std::nullopt;
    if (auto r = objects->load_model(vehicle.file, at, field, lights_of); !r) return r.error();
    objects->object_draws_.push_back({first, objects->objects_.size()});
  }
  // What each draw is in the ground truth: the glTF floor's (loaded first), then each scene object's.
  for (ObjectDraw& o : objects->objects_) o.ground_truth = LAGOON_GT_FLOOR;
  for (size_t object = 0; object < objects->object_draws_.size(); ++object)
    for (size_t i = objects->object_draws_[object].first; i < objects->object_draws_[object].second; ++i)
      objects->objects_[i].ground_truth = LAGOON_GT_OBJECT0 + uint32_t(object);
  objects->ground_truth_pipeline_ =
      vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_mesh_vert,
                                         .fragment = &shaders::render_mesh_aov_frag,
                                         .color_formats = {kGroundTruthFormat, kGroundTruthFormat},
                                         .depth_format = depth_format,
                                         .depth_test = true,
                                         .depth_write = true,
                                         .spec = {{LAGOON_MESH_SPEC_MODE, LAGOON_MESH_LIT}}});
  objects->upload_materials();
  return objects;
}

Result<void> SceneObjects::load_floor(const scene::Scene& scene) {
  const scene::Seafloor& floor = scene.seafloor;
  // A glTF sea floor is drawn like an object: the passes clip it at the water line like everything else.
  if (floor.type == scene::SeafloorType::Gltf)
    return load_model(floor.file, glm::mat4(1.0f), "seafloor.file");
  if (floor.type != scene::SeafloorType::Slope) return {};
  const FloorMesh mesh =
      build_slope_floor(floor, glm::vec2(scene.camera.position.x, scene.camera.position.z));
  floor_ = upload_mesh(ctx_, mesh.vertices, mesh.indices);
  floor_above_water_ = floor.depth_near_m < 0.0f;
  floor_texture_scale_ = floor.texture_scale_m;
  gltf::Material material;
  material.base_color_factor = glm::vec4(floor.albedo, 1.0f);
  material.double_sided = true;
  gpu::MaterialGpu gpu_material = material_gpu(material);
  if (!floor.texture.empty()) {
    auto image = io::read_png(floor.texture);
    if (!image) return make_error("seafloor.texture: " + image.error().message);
    floor_texture_ = upload_texture(ctx_, *image, "floor texture");
    gpu_material.flags.y = 1u << LAGOON_TEX_BASE;
  }
  floor_material_ = uint32_t(materials_.size());
  materials_.push_back(gpu_material);
  return {};
}

Result<void> SceneObjects::load_model(const std::string& file, const glm::mat4& transform,
                                      const std::string& field, std::optional<size_t> lights_of) {
  auto model = gltf::load_gltf(file);
  if (!model) return make_error(field + ": " + model.error().message);
  if (lights_of) add_lights(*model, *lights_of, file);
  for (const std::string& warning : model->warnings)
    std::fprintf(stderr, "lagoon: warning: %s: %s\n", file.c_str(), warning.c_str());
  // Each model's images are uploaded when a material first uses them, once per colour space.
  const size_t model_id = model_count_++;
  std::vector<std::pair<uint32_t, DrawTextures>> materials;
  for (const gltf::Material& m : model->materials) {
    DrawTextures textures;
    const uint32_t index = add_material(*model, m, model_id, textures);
    materials.push_back({index, textures});
  }
  DrawTextures plain;
  plain.image.fill(&white_texture_);
  plain.sampler.fill(samplers_.repeat.get());
  for (const gltf::Instance& instance : model->instances) {
    for (const gltf::Primitive& p : model->meshes[instance.mesh].primitives) {
      std::vector<MeshVertex> vertices(p.positions.size());
      for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {p.positions[i], p.normals[i], i < p.uvs.size() ? p.uvs[i] : glm::vec2(0),
                       i < p.uvs1.size() ? p.uvs1[i] : glm::vec2(0),
                       i < p.tangents.size() ? p.tangents[i] : glm::vec4(1, 0, 0, 1)};
      ObjectDraw draw{.mesh = upload_mesh(ctx_, vertices, p.indices),
                      .world = transform * instance.world,
                      .local = instance.world};
      draw.lo = draw.hi = p.positions.empty() ? glm::vec3(0.0f) : p.positions[0];
      for (const glm::vec3& q : p.positions) draw.lo = glm::min(draw.lo, q), draw.hi = glm::max(draw.hi, q);
      draw.y_range = world_y_range(draw.world, draw.lo, draw.hi);
      draw.textures = plain;
      if (p.material >= 0) {
        std::tie(draw.material, draw.textures) = materials[size_t(p.material)];
        draw.blend = model->materials[size_t(p.material)].alpha_mode == gltf::Material::AlphaMode::Blend;
      }
      objects_.push_back(std::move(draw));
    }
  }
  return {};
}

uint32_t SceneObjects::add_material(const gltf::Model& model, const gltf::Material& material, size_t model_id,
                                    DrawTextures& textures) {
  gpu::MaterialGpu gpu_material = material_gpu(material);
  const auto refs = texture_slots(material);
  for (int i = 0; i < LAGOON_TEX_COUNT; ++i) {
    const bool srgb = i == LAGOON_TEX_BASE || i == LAGOON_TEX_EMISSIVE;  // colours; the rest is data
    textures.image[size_t(i)] = &white_texture_;
    textures.sampler[size_t(i)] = samplers_.repeat.get();
    if (refs[size_t(i)]->image < 0) continue;
    textures.image[size_t(i)] = &model_texture(model, model_id, refs[size_t(i)]->image, srgb);
    textures.sampler[size_t(i)] = sampler_for(refs[size_t(i)]->sampler);
    gpu_material.flags.y |= 1u << i;
  }
  materials_.push_back(gpu_material);
  return uint32_t(materials_.size() - 1);
}

const vk::Image& SceneObjects::model_texture(const gltf::Model& model, size_t model_id, int image,
                                             bool srgb) {
  const std::pair<size_t, bool> key{(model_id << 20) + size_t(image), srgb};
  for (const auto& [k, slot] : texture_slots_)
    if (k == key) return *textures_[slot];
  const gltf::Texture& t = model.textures[size_t(image)];
  textures_.push_back(std::make_unique<vk::Image>(upload_texture(
      ctx_, io::Image8{.width = t.width, .height = t.height, .rgba = t.rgba}, "model texture", srgb)));
  texture_slots_.push_back({key, textures_.size() - 1});
  return *textures_.back();
}

VkSampler SceneObjects::sampler_for(const gltf::Sampler& sampler) {
  for (const auto& [s, handle] : gltf_samplers_)
    if (s == sampler) return handle.get();
  gltf_samplers_.emplace_back(sampler, vk::create_sampler(ctx_, sampler_desc(sampler)));
  return gltf_samplers_.back().second.get();
}

void SceneObjects::upload_materials() {
  const std::span<const gpu::MaterialGpu> data(materials_);
  materials_buffer_ = vk::Buffer::create(
      ctx_, data.size_bytes(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
      vk::MemoryUsage::Device, "mesh materials");
  vk::upload_buffer(ctx_, materials_buffer_, std::as_bytes(data));
}

void SceneObjects::add_lights(const gltf::Model& model, size_t object, const std::string& file) {
  for (const gltf::Light& light : model.lights) {
    if (light.type == gltf::Light::Type::Directional) {
      std::fprintf(stderr,
                   "lagoon: warning: %s: directional light '%s' ignored: the sun is the scene's one\n",
                   file.c_str(), light.name.c_str());
      continue;
    }
    const bool spot = light.type == gltf::Light::Type::Spot;
    lights_.push_back({object, light.world, light.colour, light.intensity, light.range_m,
                       spot ? glm::degrees(light.inner_cone_rad) : 0.0f,
                       spot ? glm::degrees(light.outer_cone_rad) : 180.0f});
  }
}

std::vector<scene::PointLight> SceneObjects::gltf_lights(double reference_lux) const {
  std::vector<scene::PointLight> out;
  for (const ModelLight& l : lights_) {
    const glm::vec4 at = object_world_[l.object] * l.local * glm::vec4(0, 0, 0, 1);
    const float intensity = float(l.candela / reference_lux);
    const float range = l.range_m > 0 ? l.range_m : std::clamp(std::sqrt(intensity / 1e-4f), 0.1f, 1e5f);
    // glTF lights shine down their node's −z.
    const glm::vec3 axis = glm::vec3(object_world_[l.object] * l.local * glm::vec4(0, 0, -1, 0));
    out.push_back({.position = glm::vec3(at),
                   .colour = l.colour,
                   .intensity = intensity,
                   .range_m = range,
                   .spot_direction = glm::length(axis) > 0 ? axis : glm::vec3(0, -1, 0),
                   .spot_inner_deg = l.inner_deg,
                   .spot_outer_deg = l.outer_deg});
  }
  return out;
}

void SceneObjects::place(size_t object, const glm::mat4& model_to_world) {
  if (object < object_world_.size()) object_world_[object] = model_to_world;
  const auto [first, end] = object_draws_.at(object);
  for (size_t d = first; d < end; ++d) {
    objects_[d].world = model_to_world * objects_[d].local;
    objects_[d].y_range = world_y_range(objects_[d].world, objects_[d].lo, objects_[d].hi);
  }
}

glm::vec4 SceneObjects::submerged_screen_rect(const glm::mat4& view_proj) const {
  glm::vec4 rect(1.0f, 1.0f, 0.0f, 0.0f);
  for (const ObjectDraw& o : objects_) {
    if (o.y_range.x >= 0.0f) continue;  // wholly above the water: not drawn by the refraction pass
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner(k & 1 ? o.hi.x : o.lo.x, k & 2 ? o.hi.y : o.lo.y, k & 4 ? o.hi.z : o.lo.z);
      const glm::vec4 clip = view_proj * (o.world * glm::vec4(corner, 1.0f));
      if (clip.w < 1e-3f) return {0.0f, 0.0f, 1.0f, 1.0f};
      const glm::vec2 uv(0.5f + 0.5f * clip.x / clip.w, 0.5f - 0.5f * clip.y / clip.w);  // as the shaders map
      rect = glm::vec4(glm::min(glm::vec2(rect), uv), glm::max(glm::vec2(rect.z, rect.w), uv));
    }
  }
  return rect;
}

void SceneObjects::draw_mesh(const FrameContext& frame, gpu::MeshMode mode, const GpuMesh& mesh,
                             const gpu::MeshPush& push, const DrawTextures& t, bool blend) const {
  const vk::GraphicsPipeline& pipeline = (blend ? blend_pipelines_ : pipelines_)[uint32_t(mode)];
  auto tex = [&](int i) { return sampled(*t.image[size_t(i)], t.sampler[size_t(i)]); };
  vk::draw(
      frame.cmd, pipeline,
      {vk::bind(LAGOON_MESH_BIND_FRAME, frame.uniforms()), vk::bind(LAGOON_MESH_BIND_VERTICES, mesh.vertices),
       vk::bind(LAGOON_MESH_BIND_INDICES, mesh.indices),
       vk::bind(LAGOON_MESH_BIND_ALBEDO, tex(LAGOON_TEX_BASE)),
       vk::bind(LAGOON_MESH_BIND_LIGHTS, frame.slot.lights),
       vk::bind(LAGOON_MESH_BIND_METAL_ROUGH, tex(LAGOON_TEX_METAL_ROUGH)),
       vk::bind(LAGOON_MESH_BIND_NORMAL, tex(LAGOON_TEX_NORMAL)),
       vk::bind(LAGOON_MESH_BIND_OCCLUSION, tex(LAGOON_TEX_OCCLUSION)),
       vk::bind(LAGOON_MESH_BIND_EMISSIVE, tex(LAGOON_TEX_EMISSIVE)),
       vk::bind(LAGOON_MESH_BIND_MATERIALS, materials_buffer_),
       vk::bind(LAGOON_MESH_BIND_ENVIRONMENT, sampled(environment_.image(), environment_sampler_.get())),
       vk::bind(LAGOON_MESH_BIND_DFG, sampled(dfg_texture_, samplers_.clamp.get()))},
      push, mesh.index_count);
}

void SceneObjects::draw(const FrameContext& frame, gpu::MeshMode mode) const {
  // The viewer the draws are sorted for: in the reflection, the camera mirrored about the water level.
  glm::vec3 eye = frame.scene.camera.position;
  if (mode == gpu::MeshMode::Mirrored) eye.y = -eye.y;
  std::vector<std::pair<float, const ObjectDraw*>> blended;
  for (const ObjectDraw& o : objects_) {
    // mesh.frag keeps only what is on its pass's side of y = 0; a mesh wholly on the other side is skipped.
    const bool wanted = mode == gpu::MeshMode::Refraction ? o.y_range.x < 0.0f : o.y_range.y > 0.0f;
    if (!wanted) continue;
    if (o.blend) {
      const glm::vec3 centre = glm::vec3(o.world * glm::vec4(0.5f * (o.lo + o.hi), 1.0f));
      blended.push_back({glm::length(centre - eye), &o});
      continue;
    }
    draw_mesh(frame, mode, o.mesh, {.model = o.world, .material = o.material}, o.textures, false);
  }
  // BLEND after everything opaque, farthest first (by the centre of each primitive's bounds).
  std::stable_sort(blended.begin(), blended.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [distance, o] : blended)
    draw_mesh(frame, mode, o->mesh, {.model = o->world, .material = o->material}, o->textures, true);
  // A beach: the slope floor's dry land, above the water and in its reflection (mesh.frag clips the rest).
  if (floor_ && floor_above_water_ && mode != gpu::MeshMode::Refraction) draw_floor_as(frame, mode);
}

SceneObjects::DrawTextures SceneObjects::floor_textures() const {
  DrawTextures t;
  t.image.fill(&white_texture_);
  t.sampler.fill(samplers_.repeat.get());
  if (materials_[floor_material_].flags.y != 0u) t.image[LAGOON_TEX_BASE] = &floor_texture_;
  return t;
}

void SceneObjects::draw_floor(const FrameContext& frame) const {
  if (floor_) draw_floor_as(frame, gpu::MeshMode::Refraction);
}

void SceneObjects::draw_floor_as(const FrameContext& frame, gpu::MeshMode mode) const {
  const gpu::MeshPush push{.model = glm::mat4(1.0f),
                           .material = floor_material_,
                           .texture_scale = floor_texture_scale_,
                           .height_field = 1};
  draw_mesh(frame, mode, *floor_, push, floor_textures(), false);
}

void SceneObjects::draw_ground_truth(const FrameContext& frame) const {
  // mesh_aov.frag reads only the material and its base colour (for alpha cut-outs).
  auto draw = [&](const GpuMesh& mesh, const gpu::MeshPush& push, const DrawTextures& t) {
    vk::draw(
        frame.cmd, ground_truth_pipeline_,
        {vk::bind(LAGOON_MESH_BIND_FRAME, frame.uniforms()),
         vk::bind(LAGOON_MESH_BIND_VERTICES, mesh.vertices), vk::bind(LAGOON_MESH_BIND_INDICES, mesh.indices),
         vk::bind(LAGOON_MESH_BIND_ALBEDO, sampled(*t.image[LAGOON_TEX_BASE], t.sampler[LAGOON_TEX_BASE])),
         vk::bind(LAGOON_MESH_BIND_MATERIALS, materials_buffer_)},
        push, mesh.index_count);
  };
  for (const ObjectDraw& o : objects_)
    draw(o.mesh, {.model = o.world, .material = o.material, .ground_truth = o.ground_truth}, o.textures);
  if (!floor_) return;
  draw(*floor_,
       {.model = glm::mat4(1.0f),
        .material = floor_material_,
        .texture_scale = floor_texture_scale_,
        .ground_truth = LAGOON_GT_FLOOR},
       floor_textures());
}

}  // namespace lagoon::render
