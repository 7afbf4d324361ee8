// The demo's scene: the renderer rebuilt when an edit changes what it is built from, --script steps, reset
// to the file, saving, and the status line that reports all of them.
#include <imgui.h>

#include <cstdio>

#include "demo.h"
#include "render/water_luts.h"
#include "scene/scene_io.h"

namespace lagoon::demo {
namespace {

// What the renderer was built from: a change needs a new renderer (ocean spectrum, LUTs, meshes).
std::string heavy_key(const scene::Scene& s) {
  const nlohmann::ordered_json j = scene::scene_to_json(s, {});
  nlohmann::ordered_json key;
  for (const char* block : {"ocean", "water", "seafloor", "objects", "vehicles", "wakes", "sediment"})
    if (j.contains(block)) key[block] = j[block];
  key["sun_elevation_deg"] = s.sun.elevation_deg;  // the LUTs depend on the sun's height
  return safe_dump(key);
}

}  // namespace

void Demo::message(std::string text) {
  std::fprintf(stderr, "lagoon-demo: %s\n", text.c_str());
  status_ = std::move(text);
}

Result<void> Demo::rebuild_renderer() {
  const std::string key = heavy_key(scene_);
  if (renderer_ && key == renderer_key_) return {};
  if (key == failed_key_) return {};  // already reported; wait for another change
  if (ctx_) ctx_->wait_idle();
  // The vehicles keep their tracks (and what the helm ordered) unless the vehicles themselves changed.
  const std::string vehicles =
      safe_dump(scene::scene_to_json(scene_, {}).value("vehicles", nlohmann::ordered_json()));
  const bool keep_tracks = renderer_ && vehicles == vehicles_key_;
  auto renderer = render::OceanRenderer::create(*ctx_, scene_,
                                                keep_tracks ? renderer_->tracks() : world::VehicleTracks{});
  if (!renderer) {
    failed_key_ = key;
    return make_error(renderer.error().message);
  }
  renderer_ = std::move(*renderer);
  renderer_key_ = key;
  if (!keep_tracks) helm_.release();
  vehicles_key_ = vehicles;
  failed_key_.clear();
  query_ = std::make_unique<ocean::WaveQuery>(scene_.ocean);
  probe_.reset();
  if (auto inputs = render::scene_lut_inputs(scene_)) {
    if (auto lut = optics::build_water_lut(*inputs)) lut_ = std::move(*lut);
  }
  return {};
}

// Heavy edits (spectrum, cascades, water type...) rebuild the renderer once the widget is released;
// rebuild_renderer() itself checks whether the edit touched what the renderer is built from.
void Demo::rebuild_after_edits() {
  if (scene_edited_ && !ImGui::IsAnyItemActive()) {
    scene_edited_ = false;
    if (auto r = rebuild_renderer(); !r) message(r.error().message);
  }
}

void Demo::apply_script(long long frame) {
  for (const ScriptStep& step : options_.script) {
    if (step.frame != frame) continue;
    // Not a scene field: resizes the window, as a user dragging its corner would.
    if (step.assignment.rfind("window.size=", 0) == 0) {
      resize_window(step.assignment, frame);
      continue;
    }
    if (script_helm(step.assignment, frame)) continue;   // not a scene field either: the arrow keys
    if (script_model(step.assignment, frame)) continue;  // nor this: the model selector
    const scene::Camera before = scene_.camera;
    if (auto r = edit_scene(scene_, step.assignment); !r) {
      message("script, frame " + std::to_string(frame) + ": " + step.assignment + ": " + r.error().message);
      continue;
    }
    scene_edited_ = true;
    follow_camera_edit(before);
  }
}

// A script's "window.size=WIDTHxHEIGHT".
void Demo::resize_window(const std::string& assignment, long long frame) {
  unsigned w = 0, h = 0;
  if (std::sscanf(assignment.c_str() + 12, "%ux%u", &w, &h) == 2 && w >= 16 && h >= 16 && w <= 16384 &&
      h <= 16384)
    glfwSetWindowSize(window_->handle(), int(w), int(h));
  else
    message("script, frame " + std::to_string(frame) + ": " + assignment +
            ": expected window.size=WIDTHxHEIGHT, 16 to 16384 pixels each");
}

// An edit that moved the scene's camera (position or look_at) moves the one being flown, in the same mode.
void Demo::follow_camera_edit(const scene::Camera& before) {
  if (scene_.camera.position != before.position || scene_.camera.look_at != before.look_at)
    camera_.emplace(scene_.camera, camera_->mode());
}

// Back to the scene as loaded: edits (and the panel's rejected one) dropped, its camera and time restored.
void Demo::reset_to_file() {
  scene_ = file_scene_;
  scene_edited_ = true;
  panel_.discard_pending();
  camera_.emplace(scene_.camera);
  time_s_ = scene_.time_s;
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

}  // namespace lagoon::demo
