#include "camera_controller.h"

#include <algorithm>
#include <cmath>

#include "core/compass.h"

namespace lagoon::demo {
namespace {

glm::vec3 direction(float yaw_deg, float pitch_deg) {
  return glm::vec3(compass::direction_deg(yaw_deg, pitch_deg));
}

}  // namespace

CameraController::CameraController(const scene::Camera& camera, Mode mode)
    : mode_(mode), position_(camera.position), target_(camera.look_at) {
  const glm::vec3 d = glm::normalize(camera.look_at - camera.position);
  yaw_deg_ = float(glm::degrees(compass::azimuth_of({d.x, d.z})));
  pitch_deg_ = std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -kMaxPitchDeg, kMaxPitchDeg);
  speed_ = std::clamp(glm::length(camera.look_at - camera.position) / 4.0f, 1.0f, 50.0f);
}

glm::vec3 CameraController::forward() const {
  return direction(yaw_deg_, pitch_deg_);
}

void CameraController::set_mode(Mode mode) {
  if (mode == Mode::Orbit && mode_ == Mode::Fly) {
    // Orbit what is in front: the point where the view meets the water, or a point ahead.
    const glm::vec3 f = forward();
    // Only from above the water: below it, looking down never meets the surface in front.
    const float t = f.y < -0.05f && position_.y > 0.0f ? -position_.y / f.y : 20.0f;
    target_ = position_ + f * std::min(t, 200.0f);
  }
  mode_ = mode;
}

void CameraController::update(const CameraInput& input, float dt_s) {
  dt_s = std::clamp(dt_s, 0.0f, 0.25f);  // a stall must not fling the camera away
  if (mode_ == Mode::Fly) speed_ = std::clamp(speed_ * std::pow(1.2f, input.scroll), kMinSpeed, kMaxSpeed);
  // Mouse right turns the view towards the screen's right (glm::lookAt's side vector, f x up): clockwise
  // seen from above, so the compass yaw grows.
  yaw_deg_ = std::fmod(yaw_deg_ + input.look.x * kDegreesPerPixel + 360.0f, 360.0f);
  pitch_deg_ = std::clamp(pitch_deg_ - input.look.y * kDegreesPerPixel, -kMaxPitchDeg, kMaxPitchDeg);
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::vec3(-f.z, 0.0f, f.x));  // f x up: the screen's right
  const float step = speed_ * (input.fast ? 4.0f : 1.0f) * dt_s;
  if (mode_ == Mode::Fly) {
    position_ += (right * input.move.x + glm::vec3(0, 1, 0) * input.move.y + f * input.move.z) * step;
    target_ = position_ + f;
    return;
  }
  // Orbit: WASD moves the target over the water, scroll zooms, the mouse turns around the target.
  const glm::vec3 ahead = glm::normalize(glm::vec3(f.x, 0.0f, f.z));
  target_ += (right * input.move.x + ahead * input.move.z + glm::vec3(0, 1, 0) * input.move.y) * step;
  const float distance =
      std::clamp(glm::length(position_ - target_) * std::pow(0.85f, input.scroll), 1.0f, 5000.0f);
  position_ = target_ - f * distance;
}

void CameraController::apply(scene::Camera& camera) const {
  camera.position = position_;
  camera.look_at = mode_ == Mode::Orbit ? target_ : position_ + forward();
}

}  // namespace lagoon::demo
