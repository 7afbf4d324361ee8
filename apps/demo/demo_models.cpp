// The demo's model selector (issue 15): the surface models side by side in one window, switched live. The
// renderer rebuilds from the edited scene as for any panel edit. A model's needs of the other fields
// (ocean/model_constraints.h: sines moves points only vertically, so choppiness 0) hold while it runs, and
// the old values come back after.
#include <imgui.h>

#include "demo.h"
#include "ocean/model_constraints.h"

namespace lagoon::demo {
namespace {

constexpr auto& kModels = ocean::kSurfaceModels;

}  // namespace

void Demo::select_model(ocean::SurfaceModel model) {
  ocean::OceanParams& o = scene_.ocean;
  if (o.model == model) return;
  for (const auto& [member, value] : replaced_for_model_) o.*member = value;
  replaced_for_model_.clear();
  for (const ocean::ModelConstraint& c : ocean::model_constraints(model))
    if (o.*c.member != c.value) {
      replaced_for_model_.push_back({c.member, o.*c.member});
      o.*c.member = c.value;
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
