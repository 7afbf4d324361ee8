// The frame renderer: the FFT ocean (compute/ocean/gpu) drawn over an analytic sky whose light comes from
// the optics model, water colour from the optics LUTs, then tone mapping (seed 000's eq. 18) and gamma.
// Passes: ocean step, refraction (the floor's and submerged objects' albedo and depth), reflection (objects
// above the water, mirrored), surface (the objects, then the clipmap mesh, Fresnel between the reflection
// and eq. 22 with the LUTs, foam), sky (depth-tested at the far plane, so only where nothing else was
// drawn). Surface and sky shaders tone-map their own output (exposure, eq. 18, gamma) into RGBA8.
// docs/rendering.md has the details.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "io/png.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/gpu_mesh.h"
#include "render/sky_light.h"
#include "render/surface_grid.h"
#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/handle.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class OceanRenderer {
 public:
  static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // display-referred (tone-mapped)
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  // Before a still frame the ocean runs this long (in kWarmupStep steps) so foam has built up.
  static constexpr double kWarmupS = 3.0;
  static constexpr double kWarmupStep = 0.1;

  // Fails with a message naming the file when a file the scene names (floor texture, water table) cannot be
  // used; Vulkan failures throw (VK_CHECK).
  static Result<std::unique_ptr<OceanRenderer>> create(vk::Context& ctx, const scene::Scene& scene);
  ~OceanRenderer();

  // Frames that may be in flight at once: each slot has its own host-written buffers and timer.
  static constexpr uint32_t kSlots = 2;

  // Renders `scene` (same ocean and water as at construction) at scene.render size and time scene.time_s,
  // and waits for it.
  io::Image8 render(const scene::Scene& scene, std::vector<vk::PassTime>* timings = nullptr);

  // Records the frame (the ocean stepped to scene.time_s, then every pass) into `cmd` for a window's frame
  // loop. Uses slot `slot` (mod kSlots): the caller must have waited for the last frame recorded with it.
  // Returns the display-referred image (kColorFormat), in COLOR_ATTACHMENT_OPTIMAL after colour writes.
  // A slow warm-up runs first, synchronously, when the time jumps (kWarmupS).
  const vk::Image& record(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent, uint32_t slot);
  // The per-pass GPU times of the last frame recorded with `slot`, once it has finished.
  std::vector<vk::PassTime> timings(uint32_t slot) const;

  // Ground truth of the water surface in the frame render() would draw
  // (shaders/render/ocean_surface_aov.frag): per pixel, rows from the top, the shading normal the surface
  // pass uses (xyz, w = foam) and the world point it is evaluated at (xyz m, w = 1; 0 where no water is
  // drawn). Objects are not drawn.
  struct SurfaceAov {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec4> normal_foam, world;
    const glm::vec4& normal_at(uint32_t x, uint32_t y) const { return normal_foam[size_t{y} * width + x]; }
    const glm::vec4& world_at(uint32_t x, uint32_t y) const { return world[size_t{y} * width + x]; }
  };
  SurfaceAov render_surface_aov(const scene::Scene& scene);

  // The ocean the frames are drawn from (e.g. for a field check after render()).
  const ocean::GpuOcean& ocean() const { return *ocean_; }

 private:
  struct Targets;
  OceanRenderer(vk::Context& ctx, const scene::Scene& scene);
  Result<void> init(const scene::Scene& scene);
  void record_frame(VkCommandBuffer cmd, const Targets& targets);
  // Steps the ocean to scene.time_s in `cmd` and fills the slot's uniforms and surface indices.
  void prepare_frame(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent, uint32_t slot);
  // The cascades' textures as bound by the surface pipelines (bindings 1, 2 and 9, four elements each).
  std::vector<vk::Binding> cascade_bindings() const;
  // The render targets and readback buffer, kept across frames of the same size (allocating ~30 MB of
  // images every frame cost lavapipe several ms).
  const Targets& targets_for(VkExtent2D extent);
  std::unique_ptr<Targets> targets_;

  vk::Context& ctx_;
  std::unique_ptr<ocean::GpuOcean> ocean_;
  double ocean_time_ = -1;
  bool reflection_on_ = true;
  glm::vec3 deep_colour_{0};
  glm::vec4 cascade_mss_{0};              // mean square slope of cascades 0..3 (ocean/slope_statistics.h)
  float subgrid_mss_ = 0;                 // ... of the waves shorter than the last drawn cascade, to 1 cm
  DisplacementBound displacement_bound_;  // of the whole ocean, for culling (render/surface_grid.h)
  uint32_t surface_indices_ = 0;  // in the slot's index buffer: the clipmap cells drawn for this camera
  double lut_r_max_ = 1, lut_h_max_ = 1;
  vk::Image lut_t0_, lut_t1_;  // the colour LUTs as textures: x = r axis, y = h axis
  std::optional<GpuMesh> floor_;
  struct ObjectDraw {
    GpuMesh mesh;
    glm::mat4 world{1.0f};
    glm::vec4 base_colour{1.0f};  // a = 1 when `texture` is used
    int texture = -1;             // index into textures_
  };
  std::vector<ObjectDraw> objects_;
  std::vector<vk::Image> textures_;
  vk::Image floor_texture_, white_texture_;
  bool floor_textured_ = false;
  glm::vec3 floor_albedo_{1};
  float floor_texture_scale_ = 1;
  vk::GraphicsPipeline sky_, surface_;
  vk::GraphicsPipeline mesh_hdr_, mesh_display_;  // objects into HDR targets / into the displayed frame
  vk::GraphicsPipeline surface_aov_;              // created on first use of render_surface_aov
  Result<void> load_objects(const scene::Scene& scene);
  Result<void> load_model(const std::string& file, const glm::mat4& transform, const std::string& field);
  void draw_objects(VkCommandBuffer cmd, float mode) const;
  static constexpr size_t kMaxLights = 64;  // the scene format's limit
  struct Slot {
    vk::Buffer frame;            // gpu::FrameUniforms
    vk::Buffer lights;           // gpu::PointLightGpu[kMaxLights]
    vk::Buffer surface_indices;  // the clipmap's triangles (render/surface_grid.h)
    vk::GpuTimer timer;
  };
  std::array<Slot, kSlots> slots_;
  uint32_t slot_ = 0;  // of the frame being recorded
  vk::Unique<VkSampler> repeat_sampler_, clamp_sampler_, nearest_sampler_;
};

}  // namespace lagoon::render
