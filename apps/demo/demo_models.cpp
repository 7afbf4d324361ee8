// The demo's model selector (issue 15): the surface models side by side in one window, switched live. The
// renderer rebuilds from the edited scene as for any panel edit. Sines moves points only vertically, so the
// demo sets choppiness 0 while it runs and gives the old value back after.
#include <imgui.h>

#include "demo.h"

namespace lagoon::demo {
namespace {

constexpr ocean::SurfaceModel kModels[] = {ocean::SurfaceModel::Fft, ocean::SurfaceModel::Gerstner,
                                           ocean::SurfaceModel::Sines, ocean::SurfaceModel::Perlin,
                                           ocean::SurfaceModel::Springs};

}  // namespace

void Demo::select_model(ocean::SurfaceModel model) {
  ocean::OceanParams& o = scene_.ocean;
  if (o.model == model) return;
  if (o.model == ocean::SurfaceModel::Sines && choppiness_before_sines_ >= 0) {
    o.choppiness = choppiness_before_sines_;
    choppiness_before_sines_ = -1;
  }
  if (model == ocean::SurfaceModel::Sines && o.choppiness != 0) {
    choppiness_before_sines_ = o.choppiness;
    o.choppiness = 0;
  }
  o.model = model;
  scene_edited_ = true;
  message(std::string("model ") + ocean::to_string(model) + " (M: next model)");
}

void Demo::next_model() {
  size_t i = 0;
  while (i < std::size(kModels) && kModels[i] != scene_.ocean.model) ++i;
  select_model(kModels[(i + 1) % std::size(kModels)]);
}

// One button per model, the current one marked.
void Demo::draw_model_selector() {
  ImGui::TextUnformatted("model");
  for (ocean::SurfaceModel m : kModels) {
    ImGui::SameLine();
    if (ImGui::RadioButton(ocean::to_string(m), scene_.ocean.model == m)) select_model(m);
  }
}

// A script's "model=NAME" or "model=next", as the buttons and M. False when `assignment` is not one.
bool Demo::script_model(const std::string& assignment, long long frame) {
  if (assignment.rfind("model=", 0) != 0) return false;
  const std::string name = assignment.substr(6);
  ocean::SurfaceModel m;
  if (name == "next")
    next_model();
  else if (ocean::from_string(name, m))
    select_model(m);
  else
    message("script, frame " + std::to_string(frame) + ": " + assignment +
            ": no such model; use fft, gerstner, sines, perlin, springs or next");
  return true;
}

}  // namespace lagoon::demo
