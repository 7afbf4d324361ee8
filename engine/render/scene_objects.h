// The scene's meshes on the GPU: the glTF objects (objects[]) and vehicles (vehicles[]), a glTF sea floor,
// and the procedural slope floor, with their glTF materials, textures and samplers, the pre-filtered sky
// they are lit by, and the mesh pipelines (shaders/render/mesh.*). Passes draw them in one of the modes of
// shared/mesh.h.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "gltf/model.h"
#include "render/environment_map.h"
#include "render/frame_context.h"
#include "render/gpu_mesh.h"
#include "render/samplers.h"
#include "scene/scene.h"
#include "shared/mesh.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class SceneObjects {
 public:
  // Fails with a message naming the scene field and the file when a model or the floor texture cannot be
  // used.
  static Result<std::unique_ptr<SceneObjects>> load(vk::Context& ctx, const scene::Scene& scene,
                                                    const Samplers& samplers, VkFormat display_format,
                                                    VkFormat hdr_format, VkFormat depth_format);

  // Every object, in `mode`: LAGOON_MESH_LIT into the displayed frame, the others into HDR targets.
  void draw(const FrameContext& frame, gpu::MeshMode mode) const;
  // The procedural slope floor (refraction only; a glTF floor is an object). No-op without one.
  void draw_floor(const FrameContext& frame) const;
  void draw_floor_as(const FrameContext& frame, gpu::MeshMode mode) const;
  // Every mesh and the floor, above and below the water, into ground-truth targets (two kGroundTruthFormat
  // colour targets and the depth format, as the water surface's: shaders/render/mesh_aov.frag).
  static constexpr VkFormat kGroundTruthFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  void draw_ground_truth(const FrameContext& frame) const;
  // Moves scene object `object` (objects[object], then vehicles[object - objects.size()]) to
  // `model_to_world`: a floating body's or a vehicle's pose.
  void place(size_t object, const glm::mat4& model_to_world);
  // The glTF lights of objects and vehicles (their lights_from_gltf) where they are now, as scene point
  // lights: a light of I candela has intensity I / reference_lux (the irradiance 1 m away in units of the
  // light above the water, render::reference_illuminance_lux); without a glTF range, range_m is where that
  // irradiance falls to 1e-4. Spot lights keep their cone, along their node's −z.
  std::vector<scene::PointLight> gltf_lights(double reference_lux) const;
  // The screen rectangle (uv: xy least, zw greatest) that holds every object drawn under the water from
  // `view_proj`, from its bounding box: where the refracted rays can meet something other than the floor
  // (common/refracted_hit.glsl searches only there). The whole screen when a box reaches behind the camera;
  // empty (x > z) when nothing is under the water.
  glm::vec4 submerged_screen_rect(const glm::mat4& view_proj) const;
  // The sky the objects are lit by (their pre-filtered environment); call before the frame's first draw.
  void set_sky(const SkyLight& light) { environment_.update(light); }

 private:
  SceneObjects(vk::Context& ctx, const Samplers& samplers);
  Result<void> load_floor(const scene::Scene& scene);
  // `lights_of`: the scene object whose lights the model's KHR_lights_punctual lights become (none: ignored).
  Result<void> load_model(const std::string& file, const glm::mat4& transform, const std::string& field,
                          std::optional<size_t> lights_of = std::nullopt);
  void add_lights(const gltf::Model& model, size_t object, const std::string& file);
  // A material's textures and samplers for a draw (one per LAGOON_TEX_*; a white texture where it has none).
  struct DrawTextures {
    std::array<const vk::Image*, LAGOON_TEX_COUNT> image{};
    std::array<VkSampler, LAGOON_TEX_COUNT> sampler{};
  };
  void draw_mesh(const FrameContext& frame, gpu::MeshMode mode, const GpuMesh& mesh,
                 const gpu::MeshPush& push, const DrawTextures& textures, bool blend) const;
  DrawTextures floor_textures() const;
  // The material's index in materials_, its images uploaded (each once per colour space) and samplers made.
  // `model_id` tells this model's images from other models'.
  uint32_t add_material(const gltf::Model& model, const gltf::Material& material, size_t model_id,
                        DrawTextures& textures);
  const vk::Image& model_texture(const gltf::Model& model, size_t model_id, int image, bool srgb);
  VkSampler sampler_for(const gltf::Sampler& sampler);
  void upload_materials();

  struct ObjectDraw {
    GpuMesh mesh;
    glm::mat4 world{1.0f};
    glm::mat4 local{1.0f};         // within its model (the glTF node's transform)
    glm::vec3 lo{0.0f}, hi{0.0f};  // its vertices' bounds within the node
    uint32_t material = 0;         // index into materials_
    DrawTextures textures;
    bool blend = false;         // alphaMode BLEND: drawn after the rest, farthest first
    glm::vec2 y_range{0.0f};    // lowest and highest world y of its vertices
    uint32_t ground_truth = 0;  // shared/ground_truth.h LAGOON_GT_*
  };
  vk::Context& ctx_;
  const Samplers& samplers_;
  std::vector<ObjectDraw> objects_;
  std::vector<std::pair<size_t, size_t>> object_draws_;  // per scene object, its range in objects_
  struct ModelLight {
    size_t object;
    glm::mat4 local;  // the light's node within its model
    glm::vec3 colour;
    float candela, range_m;
    float inner_deg, outer_deg;  // a spot's cone; outer 180 = a point light
  };
  std::vector<ModelLight> lights_;
  std::vector<glm::mat4> object_world_;  // per scene object, then per vehicle: its model-to-world transform
  size_t model_count_ = 0;
  std::vector<std::unique_ptr<vk::Image>> textures_;  // stable addresses for DrawTextures
  std::vector<std::pair<std::pair<size_t, bool>, size_t>> texture_slots_;  // (model image, sRGB) -> textures_
  std::vector<std::pair<gltf::Sampler, vk::Unique<VkSampler>>> gltf_samplers_;
  vk::Unique<VkSampler> environment_sampler_;  // repeats around the horizon, clamps at the poles
  vk::Image dfg_texture_;                      // render/dfg_table.h
  vk::Image white_texture_;
  std::vector<gpu::MaterialGpu> materials_;
  vk::Buffer materials_buffer_;
  EnvironmentMap environment_;
  std::optional<GpuMesh> floor_;
  vk::Image floor_texture_;
  uint32_t floor_material_ = 0;
  float floor_texture_scale_ = 1;
  bool floor_above_water_ = false;  // the slope rises out of the water (a beach): drawn above it too
  // One per gpu::MeshMode (LAGOON_MESH_SPEC_MODE): Lit into the displayed frame, the others into HDR targets;
  // opaque and MASK materials, then BLEND ones (blending, no depth writes).
  std::array<vk::GraphicsPipeline, 4> pipelines_;
  std::array<vk::GraphicsPipeline, 4> blend_pipelines_;
  vk::GraphicsPipeline ground_truth_pipeline_;  // draw_ground_truth()
};

}  // namespace lagoon::render
