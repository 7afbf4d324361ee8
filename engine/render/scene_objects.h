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

 private:
  SceneObjects(vk::Context& ctx, const Samplers& samplers) : ctx_(ctx), samplers_(samplers) {}
  Result<void> load_floor(const scene::Scene& scene);
  Result<void> load_model(const std::string& file, const glm::mat4& transform, const std::string& field);
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
