// The demo at the helm of a vehicle (issue 14): H takes the next vehicle, the arrow keys (or a script's
// helm.throttle / helm.rudder) steer it, and each changed order goes to the vehicle's track, which its body,
// wake and sediment follow (world/vehicle_tracks.h).
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "demo.h"

namespace lagoon::demo {
namespace {

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

}  // namespace

// None -> vehicles[0] -> vehicles[1] -> ... -> none.
void Demo::next_helm() {
  const size_t count = renderer_->tracks().size();
  const size_t next = helm_.vehicle() ? *helm_.vehicle() + 1 : 0;
  if (next >= count) {
    if (helm_.vehicle())
      message("let go of the helm; the vehicle holds its course");
    else
      message("no vehicle to take the helm of (the scene's vehicles[] is empty)");
    helm_.release();
    return;
  }
  helm_.take(next, renderer_->tracks()[next]->at(time_s_));
  message("at the helm of " + scene_.vehicles[next].name + ": Up / Down speed, Left / Right rudder, H next");
}

// The order for the frame from `from_s` to from_s + dt, given to the track at from_s: the bodies, wakes and
// sediment have reached that time, and an order changes the track only from its time on.
void Demo::steer(double from_s, double dt) {
  if (!helm_.vehicle() || *helm_.vehicle() >= renderer_->tracks().size()) return;
  const auto order = helm_.update(scripted_helm_.value_or(helm_input_), dt);
  if (order) renderer_->tracks()[*helm_.vehicle()]->order(from_s, *order);
}

// A script's "helm=NAME" (take the helm of that vehicle; "helm=" lets go), "helm.throttle=X" and
// "helm.rudder=X" (-1 .. 1, held until changed, as a key held down). False when `assignment` is not one.
bool Demo::script_helm(const std::string& assignment, long long frame) {
  auto fail = [&](const std::string& why) {
    message("script, frame " + std::to_string(frame) + ": " + assignment + ": " + why);
  };
  if (assignment.rfind("helm=", 0) == 0) {
    const std::string name = assignment.substr(5);
    if (name.empty()) {
      helm_.release();
      return true;
    }
    for (size_t v = 0; v < scene_.vehicles.size() && v < renderer_->tracks().size(); ++v)
      if (scene_.vehicles[v].name == name) {
        helm_.take(v, renderer_->tracks()[v]->at(time_s_));
        return true;
      }
    fail("no vehicle is named \"" + name + "\" (vehicles[].name)");
    return true;
  }
  for (const char* axis : {"helm.throttle=", "helm.rudder="}) {
    const std::string prefix(axis);
    if (assignment.rfind(prefix, 0) != 0) continue;
    char* end = nullptr;
    const std::string text = assignment.substr(prefix.size());
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(value >= -1 && value <= 1)) {
      fail("give a number from -1 to 1");
      return true;
    }
    HelmInput input = scripted_helm_.value_or(HelmInput{});
    (prefix == "helm.throttle=" ? input.throttle : input.rudder) = float(value);
    scripted_helm_ = input;
    return true;
  }
  return false;
}

void Demo::draw_helm_status() const {
  if (!helm_.vehicle()) return;
  ImGui::Text("helm: %s, %.1f m/s (ordered %.1f), turning %.0f deg/s",
              scene_.vehicles[*helm_.vehicle()].name.c_str(), helm_.speed(), helm_.ordered_speed(),
              degrees(helm_.yaw_rate()));
}

// The summary's line about the vehicle at the helm: where its track has it at the last frame's time.
void Demo::print_helm() const {
  if (!helm_.vehicle() || *helm_.vehicle() >= renderer_->tracks().size()) return;
  const physics::TrackPoint p = renderer_->tracks()[*helm_.vehicle()]->at(time_s_);
  std::printf(
      "lagoon-demo: at the helm of %s at t = %.4f s: x = %.4f m, z = %.4f m, heading %.4f deg, "
      "%.4f m/s\n",
      scene_.vehicles[*helm_.vehicle()].name.c_str(), time_s_, p.position.x, p.position.y,
      std::fmod(degrees(p.heading) + 360.0, 360.0), std::hypot(p.velocity.x, p.velocity.y));
}

}  // namespace lagoon::demo
