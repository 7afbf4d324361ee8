// The demo's input and panel: keys (F1 lists them), the camera from keys and mouse, the "Lagoon" window
// with its controls and tabs, and the wave probe under the cursor.
#include <imgui.h>

#include <cmath>
#include <ctime>
#include <glm/gtc/matrix_transform.hpp>

#include "demo.h"
#include "plots.h"
#include "render/camera.h"

namespace lagoon::demo {
namespace {

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
    "H             take the helm of the next vehicle (after the last: let go)\n"
    "M             next surface model (fft, gerstner, sines, perlin, springs)\n"
    "Arrows        at the helm: Up / Down speed, Left / Right rudder\n"
    "F12           screenshot (PNG in the working folder)\n"
    "Ctrl+S        save the scene (path in the panel)\n"
    "Ctrl+R        reset to the scene file\n"
    "Esc           quit";

std::string timestamped(const char* prefix, const char* extension) {
  const std::time_t now = std::time(nullptr);
  char text[64];
  std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", std::localtime(&now));
  return std::string(prefix) + text + extension;
}

}  // namespace

bool Demo::KeyEdges::pressed(GLFWwindow* w, int key) {
  const bool now = glfwGetKey(w, key) == GLFW_PRESS;
  const bool edge = now && !down[size_t(key)];
  down[size_t(key)] = now;
  return edge;
}

// Keys and mouse the panel does not hold (typing in a field, dragging a widget) steer the demo and camera.
void Demo::handle_input(float dt) {
  GLFWwindow* w = window_->handle();
  const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                    glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  if (!ImGui::GetIO().WantCaptureKeyboard) handle_keys(w, ctrl);
  helm_input_ = ImGui::GetIO().WantCaptureKeyboard ? HelmInput{} : helm_input(w);
  camera_->update(camera_input(w, ctrl), dt);
  camera_->apply(scene_.camera);
}

// The keys of kHelp, each acting once per press.
void Demo::handle_keys(GLFWwindow* w, bool ctrl) {
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
  if (keys_.pressed(w, GLFW_KEY_H)) next_helm();
  if (keys_.pressed(w, GLFW_KEY_M)) next_model();
  if (keys_.pressed(w, GLFW_KEY_F12)) screenshot_request_ = timestamped("lagoon-", ".png");
  if (keys_.pressed(w, GLFW_KEY_S) && ctrl) save_scene_to(save_path_);
  if (keys_.pressed(w, GLFW_KEY_R) && ctrl) {
    reset_to_file();
    message("reset to " + (scene_.source.empty() ? std::string("the defaults") : scene_.source.string()));
  }
}

// WASD/QE moves (not while Ctrl is down: Ctrl+S and Ctrl+R are commands), the right button looks around.
CameraInput Demo::camera_input(GLFWwindow* w, bool ctrl) const {
  const ImGuiIO& io = ImGui::GetIO();
  CameraInput input;
  if (!io.WantCaptureKeyboard && !ctrl) {
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
  return input;
}

// The arrow keys, for the vehicle at the helm.
HelmInput Demo::helm_input(GLFWwindow* w) const {
  auto axis = [&](int plus, int minus) {
    return float(glfwGetKey(w, plus) == GLFW_PRESS) - float(glfwGetKey(w, minus) == GLFW_PRESS);
  };
  return {axis(GLFW_KEY_UP, GLFW_KEY_DOWN), axis(GLFW_KEY_RIGHT, GLFW_KEY_LEFT)};
}

void Demo::draw_ui() {
  if (show_help_) draw_help();
  if (!show_ui_) return;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, 620), ImGuiCond_FirstUseEver);
  ImGui::Begin("Lagoon");
  draw_toolbar();
  draw_tabs();
  ImGui::End();
}

// Dynamic resolution: the size live frames are drawn at, and the frame rate it holds (resolution_scale.h).
void Demo::draw_resolution() {
  const VkExtent2D window = swapchain_->extent(), drawn = resolution_.render_extent(window);
  if (resolution_.target_fps() == 0)
    ImGui::Text("drawn at the window's size, %u x %u", window.width, window.height);
  else
    ImGui::Text("drawn at %.0f %% of the window: %u x %u of %u x %u", 100.0 * resolution_.scale(),
                drawn.width, drawn.height, window.width, window.height);
  float fps = float(resolution_.target_fps());
  if (ImGui::SliderFloat("target fps (0: full size)", &fps, 0.0f, 60.0f, "%.0f"))
    resolution_.set_target_fps(std::round(fps));
}

void Demo::draw_help() {
  ImGui::SetNextWindowPos(ImVec2(40, 40), ImGuiCond_FirstUseEver);
  ImGui::Begin("Keys (F1)", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(kHelp);
  ImGui::End();
}

// The panel's top: device and time, the buttons the keys also reach, the save path, the camera mode and
// the last message.
void Demo::draw_toolbar() {
  ImGui::Text("%s | t = %.2f s%s", ctx_->device_info().name.c_str(), time_s_, paused_ ? " (paused)" : "");
  if (ImGui::Button(paused_ ? "run" : "pause")) paused_ = !paused_;
  ImGui::SameLine();
  if (ImGui::Button("step")) step_once_ = true;
  ImGui::SameLine();
  if (ImGui::Button("screenshot")) screenshot_request_ = timestamped("lagoon-", ".png");
  ImGui::SameLine();
  if (ImGui::Button("reset")) reset_to_file();
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
  draw_model_selector();
  draw_helm_status();
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
}

void Demo::draw_tabs() {
  if (!ImGui::BeginTabBar("tabs")) return;
  if (ImGui::BeginTabItem("scene")) {
    const scene::Camera before = scene_.camera;
    if (panel_.draw(scene_)) {
      scene_edited_ = true;
      follow_camera_edit(before);
    }
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("waves & light")) {
    spectrum_plots(scene_.ocean);
    lut_images(lut_);
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("timing")) {
    draw_resolution();
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

void Demo::draw_probe() {
  // The water under the cursor, from WaveQuery (CPU, exact for the GPU's lattice): 4 times a second.
  if (!ImGui::GetIO().WantCaptureMouse && Clock::now() - last_probe_ > std::chrono::milliseconds(250) &&
      query_) {
    last_probe_ = Clock::now();
    update_probe();
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

// Samples the water where the ray through the cursor meets it (none when the ray does not point down).
void Demo::update_probe() {
  const ImGuiIO& io = ImGui::GetIO();
  const VkExtent2D e = swapchain_->extent();
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

}  // namespace lagoon::demo
