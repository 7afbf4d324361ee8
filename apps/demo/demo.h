// The Demo behind run_demo(), split by concept across files: demo_app.cpp (start-up, the loop, the summary),
// demo_frame.cpp (one frame: time, render, copy to the swapchain, present, screenshots), demo_ui.cpp (keys,
// mouse and the panel), demo_scene.cpp (the scene: edits, scripts, reset, save, renderer rebuilds).
#pragma once
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <array>
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera_controller.h"
#include "demo_options.h"
#include "exit_codes.h"
#include "helm.h"
#include "imgui_layer.h"
#include "ocean/wave_query.h"
#include "optics/lut.h"
#include "parameter_panel.h"
#include "render/cold_compile.h"
#include "render/ocean_renderer.h"
#include "resolution_scale.h"
#include "vk/buffer.h"
#include "vk/frame_ring.h"
#include "window/swapchain.h"
#include "window/window.h"

namespace lagoon::demo {

class Demo {
 public:
  using Clock = std::chrono::steady_clock;

  explicit Demo(DemoOptions options)
      : options_(std::move(options)), scene_(options_.scene), file_scene_(scene_) {}
  // Drains the device first: a frame that threw leaves its work in flight, and the renderer and the
  // swapchain go before the ring that waits for it.
  ~Demo();

  int run();

 private:
  struct KeyEdges {
    std::array<bool, GLFW_KEY_LAST + 1> down{};
    bool pressed(GLFWwindow* w, int key);  // true once per press
  };

  // Start-up and the loop (demo_app.cpp).
  int start();
  void create_acquire_semaphores();
  void print_summary() const;

  // One frame (demo_frame.cpp).
  bool frame();
  float tick();
  void observe_frame_time(float dt);
  // The caustic map's cells per side for live frames at the current dynamic resolution.
  uint32_t live_caustic_cells() const;
  void update_ui(float dt);
  scene::Scene advance_time(float dt);
  std::optional<uint32_t> acquire_image(uint32_t slot);
  void record_to_swapchain(VkCommandBuffer cmd, const scene::Scene& frame_scene, uint32_t slot,
                           uint32_t image, bool full_size);
  std::string take_screenshot_request(bool last_scripted);
  void draw_resolution();
  vk::Buffer record_screenshot_copy(VkCommandBuffer cmd, uint32_t image);
  void submit_and_present(uint32_t slot, uint32_t image);
  void finish_screenshot(const std::string& path, const vk::Buffer& pixels);
  Result<void> save_screenshot(const std::string& path, const vk::Buffer& pixels) const;
  void recreate_swapchain();

  // Input and the panel (demo_ui.cpp).
  void handle_input(float dt);
  void handle_keys(GLFWwindow* w, bool ctrl);
  CameraInput camera_input(GLFWwindow* w, bool ctrl) const;
  HelmInput helm_input(GLFWwindow* w) const;
  void next_helm();
  // The surface models (demo_models.cpp): M, the toolbar's buttons and a script's "model=NAME|next".
  void select_model(ocean::SurfaceModel model);
  void next_model();
  void draw_model_selector();
  bool script_model(const std::string& assignment, long long frame);
  void steer(double from_s, double dt);
  void draw_helm_status() const;
  void print_helm() const;
  void draw_ui();
  void draw_help();
  void draw_toolbar();
  void draw_tabs();
  void draw_probe();
  void update_probe();

  // The scene (demo_scene.cpp).
  Result<void> rebuild_renderer();
  void rebuild_after_edits();
  void apply_script(long long frame);
  void resize_window(const std::string& assignment, long long frame);
  bool script_helm(const std::string& assignment, long long frame);
  void follow_camera_edit(const scene::Camera& before);
  void reset_to_file();
  void save_scene_to(const std::string& path);
  void message(std::string text);

  DemoOptions options_;
  scene::Scene scene_, file_scene_;
  std::unique_ptr<Window> window_;
  std::unique_ptr<vk::Context> ctx_;
  std::unique_ptr<Swapchain> swapchain_;
  std::unique_ptr<ImGuiLayer> ui_;
  std::unique_ptr<vk::FrameRing> ring_;
  std::vector<vk::Unique<VkSemaphore>> acquired_;
  std::unique_ptr<render::OceanRenderer> renderer_;
  std::string renderer_key_, failed_key_;
  std::unique_ptr<ocean::WaveQuery> query_;
  optics::WaterLut lut_;
  std::optional<CameraController> camera_;
  ParameterPanel panel_;
  KeyEdges keys_;
  Helm helm_;
  HelmInput helm_input_;                    // the arrow keys this frame
  std::optional<HelmInput> scripted_helm_;  // a --script's helm.throttle / helm.rudder, held until changed
  std::string vehicles_key_;                // the vehicles the renderer's tracks were made for
  // The fields the current model needed changed (ocean/model_constraints.h), with their values before.
  std::vector<std::pair<double ocean::OceanParams::*, double>> replaced_for_model_;

  // The loop's state.
  std::array<bool, render::OceanRenderer::kSlots> slot_used_{};  // a slot's timings are readable
  double t0_ = 0;                                                // the scene's time at start
  std::unique_ptr<render::ColdCompile> cold_;  // a cold start's second device, until the first frames
  uint32_t cold_failures_ = 0;                 // its validation errors
  long long frame_ = 0;                        // frames presented
  Clock::time_point last_frame_{};
  int exit_status_ = cli::kExitOk;   // kExitFailure when the --screenshot could not be written
  long long fail_after_frame_ = -1;  // LAGOON_DEMO_FAIL_AFTER_FRAME (tests of the error path)

  double time_s_ = 0;
  long long scripted_frame_ = -1;
  bool scene_edited_ = false;  // by the panel, a script or reset since the last rebuild check
  bool paused_ = false, step_once_ = false;
  bool show_ui_ = true, show_help_ = false;
  bool vsync_ = true, swapchain_dirty_ = false;
  std::string screenshot_request_;
  char save_path_[512] = "lagoon-scene.json";
  std::string status_;
  std::deque<float> frame_ms_;
  ResolutionScale resolution_;        // live frames' size (the timing tab and --target-fps set it)
  bool last_frame_full_size_ = true;  // the frame tick() just timed was not drawn at resolution_
  std::vector<vk::PassTime> timings_;
  std::optional<ocean::WaveSample> probe_;
  glm::dvec2 probe_xz_{0};
  Clock::time_point last_probe_{};
};

}  // namespace lagoon::demo
