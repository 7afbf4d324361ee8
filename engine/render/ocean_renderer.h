// The frame renderer: the FFT ocean (compute/ocean/gpu) drawn over an analytic sky whose light comes from
// the optics model, water colour from the optics LUTs, tone mapping (seed 000's eq. 18) and gamma.
// The frame is a sequence of passes (engine/render/passes/, one file each), declared once in
// render/frame_steps.cpp:
// ocean step and wakes, caustics, refraction, reflection, surface, sky; with the camera under the water,
// ocean step, caustics, refraction, underwater; with the lens cutting the surface, both, joined by the
// waterline pass. docs/architecture.md shows the frame and how to add a pass; docs/rendering.md the shading.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "io/png.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/caustics_window.h"
#include "render/frame_context.h"
#include "render/frame_uniforms.h"
#include "render/samplers.h"
#include "render/scene_objects.h"
#include "render/surface_fields.h"
#include "render/water_luts.h"
#include "scene/scene.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/image.h"
#include "vk/pipeline_warmer.h"
#include "world/world.h"

namespace lagoon::render {

// The passes (render/passes/, one file each) stay behind the renderer: a host needs none of their headers.
class CausticsPass;
class FloatTargets;
class ObjectsPass;
class OceanStepPass;
class PipelineMemory;
class ParticlesPass;
class RefractionPass;
class SkyPass;
class SurfacePass;
class UnderwaterPass;
class WakesPass;
class WaterlinePass;

// Colour and depth images a host owns (an engine embedding Lagoon); the frame draws into them. On entry
// their contents are discarded (any layout); on exit colour is in COLOR_ATTACHMENT_OPTIMAL and depth in
// DEPTH_ATTACHMENT_OPTIMAL, made available to colour-/depth-attachment access. docs/embedding.md.
struct HostTargets {
  VkImage color = VK_NULL_HANDLE;  // OceanRenderer::kColorFormat, usage COLOR_ATTACHMENT
  VkImageView color_view = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;  // OceanRenderer::kDepthFormat, usage DEPTH_STENCIL_ATTACHMENT
  VkImageView depth_view = VK_NULL_HANDLE;
  VkExtent2D extent{};
};

class OceanRenderer {
 public:
  static constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;  // display-referred (tone-mapped)
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  static constexpr double kWarmupS = 3.0;  // OceanStepPass::kWarmupS (checked in ocean_renderer.cpp)
  // Frames that may be in flight at once: each slot has its own host-written buffers and timer.
  static constexpr uint32_t kSlots = 2;

  // Fails with a message naming the scene field when its ocean parameters are invalid or a file it names
  // (model, floor texture, water table) cannot be used. Vulkan failures throw (VK_CHECK). The vehicles follow
  // `tracks` (one per scene vehicle, e.g. the previous renderer's, steered; fresh ones when not given).
  static Result<std::unique_ptr<OceanRenderer>> create(vk::Context& ctx, const scene::Scene& scene,
                                                       world::VehicleTracks tracks = {});
  ~OceanRenderer();

  // Renders `scene` (same ocean and water as at construction) at scene.render size and time scene.time_s,
  // and waits for it.
  io::Image8 render(const scene::Scene& scene, std::vector<vk::PassTime>* timings = nullptr);

  // Records one frame of `scene` at its size without the warm-up, submits it and waits; remembers no
  // pipelines (render/pipeline_memory.h) and reads nothing back. For a second device whose only product is
  // the machine code lavapipe files in Mesa's shader cache (render/cold_compile.h).
  void draw_for_code_only(const scene::Scene& scene);

  // How a frame's state that builds up over time (foam, the wakes' waves) is reached. Continuous (the
  // default, for real time): from the last frame's, and from a warm-up from still water when the time jumps
  // (the first frame, a step back, or far ahead). Sequence (datasets, sharded renders: docs/datasets.md):
  // from the last frame's however far ahead, so a sequence whose frames are all brought about in order from
  // its first (render() or advance()) has the same state at each whichever of them are drawn. Floating
  // bodies and vehicles are always simulated from scene.bodies_start_s at a fixed step, and sediment and
  // particles are functions of time, so they need nothing.
  enum class History { Continuous, Sequence };
  void set_history(History history) { history_ = history; }
  // Brings everything that builds up over time to scene.time_s as render() would, without drawing: the
  // ocean's step (its foam), the wakes in the camera's window, the floating bodies. For the frames of a
  // sequence that another shard draws.
  void advance(const scene::Scene& scene);

  // Work that submits and waits, kept out of record(): the foam warm-up when scene.time_s jumps (the first
  // frame, a step back, or more than kWarmupS ahead; with History::Sequence only the first two), and the
  // wakes' likewise (more than wakes.history_s ahead; a frame within it that is more than a few steps ahead
  // steps the layer on here); the floating bodies are brought to scene.time_s on another thread meanwhile.
  // Call before recording a frame for scene.time_s.
  void prepare(const scene::Scene& scene);
  // Records the frame (the ocean stepped to scene.time_s, then every pass) into `cmd`; never submits. Uses
  // slot `slot` (mod kSlots): the caller must have waited for the last frame recorded with it. Returns the
  // display-referred image (kColorFormat), in COLOR_ATTACHMENT_OPTIMAL after colour writes.
  const vk::Image& record(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent, uint32_t slot);
  // The same into a host's own colour and depth images (see HostTargets).
  void record(VkCommandBuffer cmd, const scene::Scene& scene, const HostTargets& targets, uint32_t slot);
  // The per-pass GPU times of the last frame recorded with `slot`, once it has finished.
  std::vector<vk::PassTime> timings(uint32_t slot) const;

  // Ground truth of the water surface in the frame render() would draw
  // (shaders/render/ocean_surface_aov.frag): per pixel, rows from the top, the shading normal the surface
  // pass uses (xyz, w = foam) and the world point it is evaluated at (xyz m, w = 1; 0 where no water is
  // drawn). Objects are not drawn, unless `with_objects`: then every mesh and the floor too, nearest first
  // (shaders/render/mesh_aov.frag: their normal with w = 0, and w of the world point says what the pixel
  // shows, shared/ground_truth.h). dataset/ground_truth.h makes the dataset's AOVs of it.
  struct SurfaceAov {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec4> normal_foam, world;
    const glm::vec4& normal_at(uint32_t x, uint32_t y) const { return normal_foam[size_t{y} * width + x]; }
    const glm::vec4& world_at(uint32_t x, uint32_t y) const { return world[size_t{y} * width + x]; }
  };
  SurfaceAov render_surface_aov(const scene::Scene& scene, bool with_objects = false);

  // The underwater view's image formation terms in the frame render() would draw
  // (shaders/render/underwater_terms.frag, common/underwater_view.glsl): per pixel, rows from the top, the
  // light leaving what the view ray meets (rgb, a = 1 where it meets something), the share of it the water
  // lets through to the camera, and the light the water adds along the ray, in linear white units before
  // exposure and tone mapping, as if the camera were under the water (the surface is not drawn): where it is,
  // the drawn pixel is backscatter + clean · transmission. dataset/ground_truth.h keeps them where it is.
  struct UnderwaterTerms {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec4> clean, transmission, backscatter;
  };
  UnderwaterTerms render_underwater_terms(const scene::Scene& scene);

  // The floating objects' and surface vehicles' physics a frame at time_s would take from where they are,
  // in hull-seconds (the first frame and a step back replay from scene.bodies_start_s): for hosts that
  // choose each frame's time (Python) to hold it to scene::kMaxBodyHullSecondsPerFrame.
  double body_hull_seconds_to(double time_s) const { return world_->bodies().hull_seconds_to(time_s); }
  // The ocean the frames are drawn from (e.g. for a field check after render()).
  const ocean::GpuOcean& ocean() const;
  // The vehicles' tracks, shared by their bodies, wakes and sediment: an order given to one (the demo's helm)
  // moves all three from its time on.
  const world::VehicleTracks& tracks() const { return world_->tracks(); }
  // What moves in the scene and where the camera is (world/world.h): the renderer reads it every frame.
  const world::World& world() const { return *world_; }
  // The wakes (e.g. for a check of their layer after render()).
  const WakesPass& wakes() const { return *wakes_; }
  // The caustics of the last frame (e.g. for a check of their energy after render()).
  const CausticsPass& caustics() const { return *caustics_; }
  // The caustic map's cells per side for the frames that follow: LAGOON_CAUSTICS_CELLS (256, 12.5 cm, the
  // default), or 128 or 64 over the same 32 m window for a picture drawn small, where the map's fixed work
  // would be most of the frame (the demo's dynamic resolution). Other values are rounded down to one of
  // these. The blur widens with the cells' own unresolved waves.
  void set_caustic_cells(uint32_t cells);
  uint32_t caustic_cells() const { return caustic_cells_; }
  // Where the camera is judged to be (above, below, cutting the surface); tests and tools may force a side.
  world::CameraMedium& camera_medium() { return world_->camera_medium(); }
  // The side a frame of `scene` at `extent` is drawn for (its near plane's reach allowed for).
  world::CameraSide camera_side(const scene::Scene& scene, VkExtent2D extent);

 private:
  explicit OceanRenderer(vk::Context& ctx);
  Result<void> init(const scene::Scene& scene, world::VehicleTracks tracks);
  // Fills the slot's uniforms, lights and surface indices, and starts the slot's timer.
  FrameContext begin_frame(VkCommandBuffer cmd, const scene::Scene& scene, VkExtent2D extent, uint32_t slot,
                           const CausticsWindow& caustics);
  // The frames the renderer records, each through the one table of render/frame_steps.cpp: its passes, the
  // frames and camera sides each joins, and the images each reads and writes.
  enum class FrameKind : uint8_t {
    Picture = 1,          // record(), render()
    SurfaceAov = 2,       // render_surface_aov
    UnderwaterTerms = 4,  // render_underwater_terms
    Advance = 8,          // advance(): the state a frame carries on, nothing drawn
  };
  struct FrameRequest {
    FrameKind kind = FrameKind::Picture;
    CausticsWindow caustics{};
    vk::Target color{}, depth{};           // Picture: the frame's own targets
    const FloatTargets* floats = nullptr;  // SurfaceAov (2 colours), UnderwaterTerms (3)
    bool objects = false;                  // SurfaceAov: the meshes' ground truth over the surface's
    // UnderwaterTerms: the caustic map and the refraction targets already hold this frame's (the picture
    // of the same scene, side and size was the last to draw them), so they are not drawn again.
    bool views_drawn = false;
  };
  // What the caustic map and the refraction targets were last drawn for: the scene, the camera's side and
  // the size (views_key); empty when unknown.
  static std::string views_key(const scene::Scene& scene, world::CameraSide side, VkExtent2D extent);
  void record_frame(const FrameContext& frame, const FrameRequest& request);
  // Files the pipelines made so far for the next run (render/pipeline_memory.h).
  void remember_pipelines();
  friend struct FrameSteps;
  // The passes' own targets, kept across frames of the same size (allocating ~30 MB of images every frame
  // cost lavapipe several ms).
  void resize(VkExtent2D extent);
  // Brings the floating objects to time_s and moves their meshes there.
  void place_floating_objects(double time_s);
  // What a frame does to the state it carries on (advance() without drawing does the same): before it is
  // recorded, the bodies to its time and the wakes' window to its camera; then the ocean's and the wakes'
  // steps to its time.
  void move_world(const scene::Scene& scene);
  // The sediment clouds at time_s into the slot's buffer (none without stirrers).
  void write_sediment(double time_s, FrameSlot& slot) const;
  // The renderer's own colour and depth (and readback) for record(extent) and render().
  struct OwnTargets;
  const OwnTargets& own_targets(VkExtent2D extent);

  vk::Context& ctx_;
  Samplers samplers_;
  WaterLuts luts_;
  std::unique_ptr<SceneObjects> objects_;
  std::unique_ptr<OceanStepPass> ocean_step_;
  std::unique_ptr<WakesPass> wakes_;
  std::optional<SurfaceFields>
      fields_;  // the ocean's cascades and the wakes, as the surface passes bind them
  OceanShading shading_;
  uint32_t caustic_cells_ = LAGOON_CAUSTICS_CELLS;  // set_caustic_cells
  float caustic_mss_ = 0;                           // the waves those cells leave out (their blur)
  std::unique_ptr<RefractionPass> refraction_;
  std::unique_ptr<ObjectsPass> reflection_;
  std::unique_ptr<SurfacePass> surface_;
  std::unique_ptr<SkyPass> sky_;
  std::unique_ptr<UnderwaterPass> underwater_;
  std::unique_ptr<ObjectsPass> window_;
  std::unique_ptr<CausticsPass> caustics_;
  std::unique_ptr<WaterlinePass> waterline_;
  std::unique_ptr<ParticlesPass> particles_;
  std::unique_ptr<world::World> world_;
  History history_ = History::Continuous;
  VkExtent2D extent_{};          // of the passes' targets
  std::string views_drawn_for_;  // views_key() of the frame that last drew the caustics and refraction
  world::CameraSide picture_side_ = world::CameraSide::Above;  // of the last picture recorded
  // The pipelines earlier runs of the scene made, made ahead on another thread. After the passes: the warmer
  // stops before the passes whose pipelines it makes go.
  std::unique_ptr<PipelineMemory> pipeline_memory_;
  std::unique_ptr<vk::PipelineWarmer> warmer_;
  std::unique_ptr<OwnTargets> own_;
  std::array<FrameSlot, kSlots> slots_;
};

}  // namespace lagoon::render
