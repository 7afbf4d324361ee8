#include "demo_app.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <deque>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>

#include "camera_controller.h"
#include "exit_codes.h"
#include "gpu_session.h"
#include "imgui_layer.h"
#include "interrupt_guard.h"
#include "io/png.h"
#include "ocean/wave_query.h"
#include "optics/lut.h"
#include "parameter_panel.h"
#include "plots.h"
#include "render/camera.h"
#include "render/ocean_renderer.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/frame_ring.h"
#include "window/swapchain.h"
#include "window/window.h"

namespace lagoon::demo {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kHelp =
    "F1            this help\n"
    "F2            show / hide the panel\n"
    "W A S D       move (fly) or move the orbit centre (orbit)\n"
    "Q E           down / up\n"
    "Shift         4x faster\n"
    "Right mouse   hold to look around (fly) or turn around the centre (orbit)\n"
    "Mouse wheel   speed (fly) or distance (orbit)\n"
    "Tab           fly / orbit\n"
    "P             pause / run time\n"
    "N             one step of 1/30 s while paused\n"
    "V             vsync on / off\n"
    "F12           screenshot (PNG in the working folder)\n"
    "Ctrl+S        save the scene (path in the panel)\n"
    "Ctrl+R        reset to the scene file\n"
    "Esc           quit";

// What the renderer was built from: a change needs a new renderer (ocean spectrum, LUTs, meshes).
std::string heavy_key(const scene::Scene& s) {
  const nlohmann::ordered_json j = scene::scene_to_json(s, {});
  nlohmann::ordered_json key;
  for (const char* block : {"ocean", "water", "seafloor", "objects"})
    if (j.contains(block)) key[block] = j[block];
  key["sun_elevation_deg"] = s.sun.elevation_deg;  // the LUTs depend on the sun's height
  return safe_dump(key);
}

std::string timestamped(const char* prefix, const char* extension) {
  const std::time_t now = std::time(nullptr);
  char text[64];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", std::localtime(&now));
  return std::string(prefix) + text + extension;
}

class Demo {
 public:
  explicit Demo(DemoOptions options)
      : options_(std::move(options)), scene_(options_.scene), file_scene_(scene_) {}

  int run();

 private:
  struct KeyEdges {
    std::array<bool, GLFW_KEY_LAST + 1> down{};
    bool pressed(GLFWwindow* w, int key) {
      const bool now = glfwGetKey(w, key) == GLFW_PRESS;
      const bool edge = now && !down[size_t(key)];
      down[size_t(key)] = now;
      return edge;
    }
  };

  Result<void> rebuild_renderer();
  void recreate_swapchain();
  void handle_input(float dt);
  void draw_ui();
  void draw_probe();
  void apply_script(long long frame);
  Result<void> save_screenshot(const std::string& path, const vk::Buffer& pixels) const;
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
  std::vector<vk::PassTime> timings_;
  std::optional<ocean::WaveSample> probe_;
  glm::dvec2 probe_xz_{0};
  Clock::time_point last_probe_{};
};

void Demo::message(std::string text) {
  std::fprintf(stderr, "lagoon-demo: %s\n", text.c_str());
  status_ = std::move(text);
}

Result<void> Demo::rebuild_renderer() {
  const std::string key = heavy_key(scene_);
  if (renderer_ && key == renderer_key_) return {};
  if (key == failed_key_) return {};  // already reported; wait for another change
  if (ctx_) ctx_->wait_idle();
  auto renderer = render::OceanRenderer::create(*ctx_, scene_);
  if (!renderer) {
    failed_key_ = key;
    return make_error(renderer.error().message);
  }
  renderer_ = std::move(*renderer);
  renderer_key_ = key;
  failed_key_.clear();
  query_ = std::make_unique<ocean::WaveQuery>(scene_.ocean);
  probe_.reset();
  if (auto inputs = optics::lut_inputs(scene_.water, scene_.sun.elevation_deg)) {
    if (auto lut = optics::build_water_lut(*inputs)) lut_ = std::move(*lut);
  }
  return {};
}

void Demo::recreate_swapchain() {
  ctx_->wait_idle();
  // The window may have been minimised since the loop looked: try again next frame.
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_->physical_device(), ctx_->surface(), &caps));
  if (caps.currentExtent.width == 0 || caps.currentExtent.height == 0) return;
  auto next = std::make_unique<Swapchain>(*ctx_, window_->framebuffer_extent(), vsync_, swapchain_.get());
  swapchain_ = std::move(next);
  ui_->on_swapchain(*swapchain_);
  swapchain_dirty_ = false;
}

void Demo::apply_script(long long frame) {
  for (const ScriptStep& step : options_.script) {
    if (step.frame != frame) continue;
    // Not a scene field: resizes the window, as a user dragging its corner would.
    if (step.assignment.rfind("window.size=", 0) == 0) {
      unsigned w = 0, h = 0;
      if (std::sscanf(step.assignment.c_str() + 12, "%ux%u", &w, &h) == 2 && w >= 16 && h >= 16 &&
          w <= 16384 && h <= 16384)
        glfwSetWindowSize(window_->handle(), int(w), int(h));
      else
        message("script, frame " + std::to_string(frame) + ": " + step.assignment +
                ": expected window.size=WIDTHxHEIGHT, 16 to 16384 pixels each");
      continue;
    }
    const scene::Camera before = scene_.camera;
    if (auto r = edit_scene(scene_, step.assignment); !r) {
      message("script, frame " + std::to_string(frame) + ": " + step.assignment + ": " + r.error().message);
      continue;
    }
    scene_edited_ = true;
    if (scene_.camera.position != before.position || scene_.camera.look_at != before.look_at)
      camera_.emplace(scene_.camera, camera_->mode());
  }
}

void Demo::handle_input(float dt) {
  GLFWwindow* w = window_->handle();
  const ImGuiIO& io = ImGui::GetIO();
  const bool keyboard = !io.WantCaptureKeyboard;
  const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                    glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  if (keyboard) {
    if (keys_.pressed(w, GLFW_KEY_F1)) show_help_ = !show_help_;
    if (keys_.pressed(w, GLFW_KEY_F2)) show_ui_ = !show_ui_;
    if (keys_.pressed(w, GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(w, GLFW_TRUE);
    if (keys_.pressed(w, GLFW_KEY_TAB))
      camera_->set_mode(camera_->mode() == CameraController::Mode::Fly ? CameraController::Mode::Orbit
                                                                       : CameraController::Mode::Fly);
    if (keys_.pressed(w, GLFW_KEY_P)) paused_ = !paused_;
    if (keys_.pressed(w, GLFW_KEY_N)) step_once_ = true;
    if (keys_.pressed(w, GLFW_KEY_V)) {
      vsync_ = !vsync_;
      swapchain_dirty_ = true;
    }
    if (keys_.pressed(w, GLFW_KEY_F12)) screenshot_request_ = timestamped("lagoon-", ".png");
    if (keys_.pressed(w, GLFW_KEY_S) && ctrl) save_scene_to(save_path_);
    if (keys_.pressed(w, GLFW_KEY_R) && ctrl) {
      scene_ = file_scene_;
      scene_edited_ = true;
      panel_.discard_pending();
      camera_.emplace(scene_.camera);
      time_s_ = scene_.time_s;
      message("reset to " + (scene_.source.empty() ? std::string("the defaults") : scene_.source.string()));
    }
  }
  CameraInput input;
  if (keyboard && !ctrl) {
    auto axis = [&](int plus, int minus) {
      return float(glfwGetKey(w, plus) == GLFW_PRESS) - float(glfwGetKey(w, minus) == GLFW_PRESS);
    };
    input.move = {axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q), axis(GLFW_KEY_W, GLFW_KEY_S)};
    input.fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
  }
  if (!io.WantCaptureMouse) {
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS)
      input.look = {io.MouseDelta.x, io.MouseDelta.y};
    input.scroll = io.MouseWheel;
  }
  camera_->update(input, dt);
  camera_->apply(scene_.camera);
}

void Demo::draw_probe() {
  // The water under the cursor, from WaveQuery (CPU, exact for the GPU's lattice): 4 times a second.
  const ImGuiIO& io = ImGui::GetIO();
  const VkExtent2D e = swapchain_->extent();
  if (!io.WantCaptureMouse && Clock::now() - last_probe_ > std::chrono::milliseconds(250) && query_) {
    last_probe_ = Clock::now();
    const auto m = render::camera_matrices(scene_.camera, float(e.width) / float(e.height));
    const glm::mat4 inv = glm::inverse(m.view_proj);
    // Window coordinates (io.DisplaySize), which differ from framebuffer pixels on HiDPI screens.
    const float x = 2.0f * io.MousePos.x / io.DisplaySize.x - 1.0f;
    const float y = 1.0f - 2.0f * io.MousePos.y / io.DisplaySize.y;
    const glm::vec4 near = inv * glm::vec4(x, y, 0.0f, 1.0f), far = inv * glm::vec4(x, y, 1.0f, 1.0f);
    const glm::dvec3 a = glm::dvec3(near) / double(near.w), b = glm::dvec3(far) / double(far.w);
    const glm::dvec3 dir = b - a;
    probe_.reset();
    if (dir.y < -1e-6) {
      double height = 0;
      for (int i = 0; i < 3; ++i) {  // meet the displaced surface, not just the mean plane
        const double t = (height - a.y) / dir.y;
        probe_xz_ = {a.x + dir.x * t, a.z + dir.z * t};
        probe_ = query_->sample(time_s_, probe_xz_.x, probe_xz_.y);
        height = probe_->height;
      }
    }
  }
  if (!probe_) {
    ImGui::TextDisabled("point at the water");
    return;
  }
  ImGui::Text("at x %.2f m, z %.2f m", probe_xz_.x, probe_xz_.y);
  ImGui::Text("height %.3f m (+/- %.3f m)", probe_->height, probe_->error_bound_m);
  ImGui::Text("normal %.3f %.3f %.3f", probe_->normal.x, probe_->normal.y, probe_->normal.z);
  ImGui::Text("velocity %.2f %.2f %.2f m/s", probe_->velocity.x, probe_->velocity.y, probe_->velocity.z);
}

void Demo::draw_ui() {
  if (show_help_) {
    ImGui::SetNextWindowPos(ImVec2(40, 40), ImGuiCond_FirstUseEver);
    ImGui::Begin("Keys (F1)", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(kHelp);
    ImGui::End();
  }
  if (!show_ui_) return;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 620), ImGuiCond_FirstUseEver);
  ImGui::Begin("Lagoon");
  ImGui::Text("%s | t = %.2f s%s", ctx_->device_info().name.c_str(), time_s_, paused_ ? " (paused)" : "");
  if (ImGui::Button(paused_ ? "run" : "pause")) paused_ = !paused_;
  ImGui::SameLine();
  if (ImGui::Button("step")) step_once_ = true;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) screenshot_request_ = timestamped("lagoon-", ".png");
  ImGui::SameLine();
  if (ImGui::Button("reset")) {
    scene_ = file_scene_;
    scene_edited_ = true;
    panel_.discard_pending();
    camera_.emplace(scene_.camera);
    time_s_ = scene_.time_s;
  }
  ImGui::SameLine();
  bool vsync = vsync_;
  if (ImGui::Checkbox("vsync", &vsync)) {
    vsync_ = vsync;
    swapchain_dirty_ = true;
  }
  ImGui::InputText("##save", save_path_, sizeof save_path_);
  ImGui::SameLine();
  if (ImGui::Button("save scene")) save_scene_to(save_path_);
  int mode = camera_->mode() == CameraController::Mode::Fly ? 0 : 1;
  if (ImGui::RadioButton("fly", &mode, 0)) camera_->set_mode(CameraController::Mode::Fly);
  ImGui::SameLine();
  if (ImGui::RadioButton("orbit", &mode, 1)) camera_->set_mode(CameraController::Mode::Orbit);
  ImGui::SameLine();
  ImGui::Text("speed %.1f m/s  F1: keys", camera_->speed_mps());
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  if (ImGui::BeginTabBar("tabs")) {
    if (ImGui::BeginTabItem("scene")) {
      const glm::vec3 position = scene_.camera.position, look_at = scene_.camera.look_at;
      if (panel_.draw(scene_)) {
        scene_edited_ = true;
        if (scene_.camera.position != position || scene_.camera.look_at != look_at)
          camera_.emplace(scene_.camera, camera_->mode());
      }
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("waves & light")) {
      spectrum_plots(scene_.ocean);
      lut_images(lut_);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("timing")) {
      frame_time_graph(frame_ms_);
      pass_time_bars(timings_);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("probe")) {
      draw_probe();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

void Demo::save_scene_to(const std::string& path) {
  scene::Scene saved = scene_;
  saved.time_s = float(time_s_);
  saved.render.width = swapchain_->extent().width;
  saved.render.height = swapchain_->extent().height;
  if (auto r = scene::save_scene(saved, path); !r)
    message(r.error().message);
  else
    message("saved the scene to " + path);
}

Result<void> Demo::save_screenshot(const std::string& path, const vk::Buffer& pixels) const {
  const VkExtent2D e = swapchain_->extent();
  io::Image8 image;
  image.width = e.width;
  image.height = e.height;
  image.rgba.resize(size_t(e.width) * e.height * 4);
  pixels.invalidate();
  std::memcpy(image.rgba.data(), pixels.mapped(), image.rgba.size());
  if (swapchain_->format() == VK_FORMAT_B8G8R8A8_UNORM)
    for (size_t i = 0; i < image.rgba.size(); i += 4) std::swap(image.rgba[i], image.rgba[i + 2]);
  return io::write_png(path, image);
}

int Demo::run() {
  // Ctrl-C or SIGTERM closes the demo as its window's close button does: the loop ends (at once when the
  // signal came during start-up), the GPU drains, and the validation result still decides the exit code.
  cli::InterruptGuard interrupt;
  auto window = Window::create(options_.width, options_.height, "Lagoon");
  if (!window) {
    std::fprintf(stderr, "lagoon-demo: %s\n", window.error().message.c_str());
    return cli::kExitFailure;
  }
  window_ = std::move(*window);
  vk::ContextOptions context_options = vk::ContextOptions::from_environment();
  context_options.instance_extensions = Window::required_instance_extensions();
  context_options.create_surface = [&](VkInstance instance) { return window_->create_surface(instance); };
  context_options.frames_in_flight = render::OceanRenderer::kSlots;
  auto ctx = vk::Context::create(context_options);
  if (!ctx) {
    std::fprintf(stderr, "lagoon-demo: %s\n", ctx.error().message.c_str());
    return cli::kExitFailure;
  }
  ctx_ = std::move(*ctx);
  vsync_ = options_.vsync;
  show_ui_ = !options_.hide_ui;
  time_s_ = scene_.time_s;
  camera_.emplace(scene_.camera);
  if (auto r = rebuild_renderer(); !r) {
    std::fprintf(stderr, "lagoon-demo: %s: %s\n", scene_.source.c_str(), r.error().message.c_str());
    return cli::kExitFailure;
  }
  swapchain_ = std::make_unique<Swapchain>(*ctx_, window_->framebuffer_extent(), vsync_);
  ui_ = std::make_unique<ImGuiLayer>(*ctx_, *window_, *swapchain_);
  ring_ = std::make_unique<vk::FrameRing>(*ctx_, render::OceanRenderer::kSlots);
  for (uint32_t i = 0; i < render::OceanRenderer::kSlots; ++i) {
    const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(ctx_->device(), &info, nullptr, &s));
    acquired_.emplace_back(ctx_->device(), s);
  }
  std::array<bool, render::OceanRenderer::kSlots> slot_used{};
  const double t0 = time_s_;
  long long frame = 0;
  Clock::time_point last = Clock::now();
  int status = cli::kExitOk;
  while (!window_->should_close() && !interrupt.signal()) {
    window_->poll_events();
    const VkExtent2D fb = window_->framebuffer_extent();
    if (fb.width == 0 || fb.height == 0) {  // minimised: nothing to draw into
      glfwWaitEventsTimeout(0.1);
      last = Clock::now();
      continue;
    }
    if (swapchain_dirty_ || fb.width != swapchain_->extent().width ||
        fb.height != swapchain_->extent().height)
      recreate_swapchain();

    const Clock::time_point now = Clock::now();
    const float dt = std::chrono::duration<float>(now - last).count();
    last = now;
    frame_ms_.push_back(dt * 1000.0f);
    if (frame_ms_.size() > 240) frame_ms_.pop_front();

    ui_->new_frame();
    handle_input(dt);
    if (options_.frames && frame != scripted_frame_) {  // once per frame, even if the frame is retried
      apply_script(frame);
      scripted_frame_ = frame;
    }
    draw_ui();
    ImGui::Render();
    // Heavy edits (spectrum, cascades, water type...) rebuild the renderer once the widget is released;
    // rebuild_renderer() itself checks whether the edit touched what the renderer is built from.
    if (scene_edited_ && !ImGui::IsAnyItemActive()) {
      scene_edited_ = false;
      if (auto r = rebuild_renderer(); !r) message(r.error().message);
    }

    // Time: exactly 1/fps per frame in scripted runs, the wall clock otherwise.
    if (options_.frames) {
      time_s_ = t0 + double(frame) / options_.fps;
    } else if (!paused_) {
      time_s_ += dt;
    } else if (step_once_) {
      time_s_ += 1.0 / 30.0;
    }
    step_once_ = false;
    time_s_ = std::min(time_s_, 86400.0);
    scene::Scene frame_scene = scene_;
    frame_scene.time_s = float(time_s_);

    renderer_->prepare(frame_scene);  // a jump in time warms the foam up here, outside the frame's recording
    VkCommandBuffer cmd = ring_->begin();
    const uint32_t slot = ring_->slot();
    if (slot_used[slot]) timings_ = renderer_->timings(slot);
    uint32_t image = 0;
    const VkResult acquire = vkAcquireNextImageKHR(ctx_->device(), swapchain_->handle(), UINT64_MAX,
                                                   acquired_[slot], VK_NULL_HANDLE, &image);
    if (acquire == VK_ERROR_OUT_OF_DATE_KHR) {
      ring_->submit();  // nothing recorded; keeps the ring's slots in step
      swapchain_dirty_ = true;
      continue;
    }
    if (acquire != VK_SUCCESS && acquire != VK_SUBOPTIMAL_KHR) VK_CHECK(acquire);
    const VkExtent2D extent = swapchain_->extent();
    const vk::Image& colour = renderer_->record(cmd, frame_scene, extent, slot);
    slot_used[slot] = true;

    // The rendered frame into the swapchain image (a blit converts RGBA to the swapchain's BGRA).
    const VkImage target = swapchain_->image(image);
    const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    const vk::Access acquired_stage{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE};
    vk::image_barrier(cmd, colour.handle(), colour.all_subresources(),
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      vk::access::kColorAttachmentWrite, vk::access::kTransferRead);
    vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      acquired_stage, vk::access::kTransferWrite);
    const VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .srcOffsets = {{0, 0, 0}, {int32_t(extent.width), int32_t(extent.height), 1}},
                             .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .dstOffsets = {{0, 0, 0}, {int32_t(extent.width), int32_t(extent.height), 1}}};
    vkCmdBlitImage(cmd, colour.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    vk::image_barrier(cmd, colour.handle(), colour.all_subresources(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kTransferRead,
                      vk::access::kColorAttachmentWrite);
    ui_->record(cmd, image, ImGui::GetDrawData());

    // A screenshot is what the window shows: the swapchain image after the UI.
    const bool last_scripted = options_.frames && frame + 1 == *options_.frames;
    std::string screenshot = std::move(screenshot_request_);
    screenshot_request_.clear();
    if (!options_.screenshot.empty() && (last_scripted || (!options_.frames && frame == 0)))
      screenshot = options_.screenshot;
    vk::Buffer pixels;
    if (!screenshot.empty()) {
      pixels = vk::Buffer::create(*ctx_, VkDeviceSize(extent.width) * extent.height * 4,
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, "screenshot");
      vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::kColorAttachmentWrite,
                        vk::access::kTransferRead);
      const VkBufferImageCopy copy{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {extent.width, extent.height, 1}};
      vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels.handle(), 1, &copy);
      vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, vk::access::kTransferRead, vk::access::kNone);
      vk::buffer_barrier(cmd, pixels.handle(), vk::access::kTransferWrite, vk::access::kHostRead);
    }
    ring_->submit({.wait = acquired_[slot],
                   .wait_stage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                   .signal = swapchain_->rendered(image)});
    const VkSemaphore rendered = swapchain_->rendered(image);
    const VkSwapchainKHR swapchain = swapchain_->handle();
    const VkPresentInfoKHR present{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                   .waitSemaphoreCount = 1,
                                   .pWaitSemaphores = &rendered,
                                   .swapchainCount = 1,
                                   .pSwapchains = &swapchain,
                                   .pImageIndices = &image};
    const VkResult presented = vkQueuePresentKHR(ctx_->queue(), &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR)
      swapchain_dirty_ = true;
    else
      VK_CHECK(presented);

    if (!screenshot.empty()) {
      ring_->wait_last();
      if (auto r = save_screenshot(screenshot, pixels); !r) {
        message(r.error().message);
        if (screenshot == options_.screenshot) status = cli::kExitFailure;
      } else {
        message("wrote " + screenshot + " (t = " + std::to_string(time_s_) + " s)");
      }
    }
    if (last_scripted && !options_.save_scene.empty()) save_scene_to(options_.save_scene);
    ++frame;
    if (last_scripted && options_.exit_after_frames) break;
  }
  ctx_->wait_idle();
  if (frame_ms_.size() > 2) {
    // Skips the first frames (pipeline compilation, warm-up), as `lagoon bench` does.
    std::vector<float> times(frame_ms_.begin() + 2, frame_ms_.end());
    std::sort(times.begin(), times.end());
    std::printf("lagoon-demo: %lld frames at %ux%u on %s; median frame time %.1f ms\n", frame,
                swapchain_->extent().width, swapchain_->extent().height, ctx_->device_info().name.c_str(),
                times[times.size() / 2]);
  }
  if (int v = cli::validation_status(*ctx_); v != cli::kExitOk) return v;
  return status;
}

}  // namespace

int run_demo(DemoOptions options) {
  Demo demo(std::move(options));
  return demo.run();
}

}  // namespace lagoon::demo
