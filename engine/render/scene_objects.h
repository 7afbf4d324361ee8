// The scene's meshes on the GPU: the glTF objects (objects[]) and vehicles (vehicles[]), a glTF sea floor,
// and the procedural slope floor, with their textures and the mesh pipelines (shaders/render/mesh.*). Passes
// draw them in one of the three modes of shared/mesh.h.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "gltf/model.h"
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
  // Moves scene object `object` (objects[object], then vehicles[object - objects.size()]) to
  // `model_to_world`: a floating body's or a vehicle's pose.
  void place(size_t object, const glm::mat4& model_to_world);
  // The objects' glTF lights (objects[].lights_from_gltf) where their objects are now, as scene point
  // lights: a light of I candela has intensity I / reference_lux (the irradiance 1 m away in units of the
  // light above the water, render::reference_illuminance_lux); without a glTF range, range_m is where that
  // irradiance falls to 1e-4. Spot lights keep their cone, along their node's −z.
  std::vector<scene::PointLight> gltf_lights(double reference_lux) const;

 private:
  SceneObjects(vk::Context& ctx, const Samplers& samplers) : ctx_(ctx), samplers_(samplers) {}
  Result<void> load_floor(const scene::Scene& scene);
  // `lights_of`: the scene object whose lights the model's KHR_lights_punctual lights become (none: ignored).
  Result<void> load_model(const std::string& file, const glm::mat4& transform, const std::string& field,
                          std::optional<size_t> lights_of = std::nullopt);
  void add_lights(const gltf::Model& model, size_t object, const std::string& file);
  void draw_mesh(const FrameContext& frame, gpu::MeshMode mode, const GpuMesh& mesh,
                 const gpu::MeshPush& push, const vk::Image& texture) const;

  struct ObjectDraw {
    GpuMesh mesh;
    glm::mat4 world{1.0f};
    glm::mat4 local{1.0f};         // within its model (the glTF node's transform)
    glm::vec3 lo{0.0f}, hi{0.0f};  // its vertices' bounds within the node
    glm::vec4 base_colour{1.0f};   // a = 1 when `texture` is used
    int texture = -1;              // index into textures_
    glm::vec2 y_range{0.0f};       // lowest and highest world y of its vertices
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
  std::vector<glm::mat4> object_world_;  // per scene object with lights: its model-to-world transform
  std::vector<vk::Image> textures_;
  vk::Image white_texture_;
  std::optional<GpuMesh> floor_;
  vk::Image floor_texture_;
  bool floor_textured_ = false;
  glm::vec3 floor_albedo_{1};
  float floor_texture_scale_ = 1;
  // One per gpu::MeshMode (LAGOON_MESH_SPEC_MODE): Lit into the displayed frame, the others into HDR targets.
  std::array<vk::GraphicsPipeline, 4> pipelines_;
};

}  // namespace lagoon::render
