// The demo's camera: fly (WASD/QE, mouse look, scroll for speed) or orbit (drag around a target, scroll to
// zoom). Pure state and maths, no window: the app turns GLFW input into CameraInput.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace lagoon::demo {

struct CameraInput {
  glm::vec3 move{0.0f};  // x = right, y = up, z = forward; each -1 .. 1
  glm::vec2 look{0.0f};  // mouse movement in pixels while the look button is held
  float scroll = 0.0f;   // wheel steps
  bool fast = false;     // shift: 4x speed
};

class CameraController {
 public:
  enum class Mode { Fly, Orbit };

  // Starts where `camera` is, looking where it looks; the orbit centre is its look_at point.
  explicit CameraController(const scene::Camera& camera, Mode mode = Mode::Fly);

  void update(const CameraInput& input, float dt_s);
  // Writes position and look_at (the rest of `camera` is left alone).
  void apply(scene::Camera& camera) const;

  Mode mode() const { return mode_; }
  void set_mode(Mode mode);
  float speed_mps() const { return speed_; }
  glm::vec3 position() const { return position_; }
  glm::vec3 forward() const;
  float yaw_deg() const { return yaw_deg_; }
  float pitch_deg() const { return pitch_deg_; }

  static constexpr float kMinSpeed = 0.25f, kMaxSpeed = 500.0f;
  static constexpr float kDegreesPerPixel = 0.15f;
  static constexpr float kMaxPitchDeg = 89.0f;

 private:
  Mode mode_ = Mode::Fly;
  glm::vec3 position_{0.0f};
  glm::vec3 target_{0.0f};  // orbit centre
  float yaw_deg_ = 0.0f;    // compass (core/compass.h), as the scene's sun and yaw_deg
  float pitch_deg_ = 0.0f;  // above the horizon
  float speed_ = 5.0f;
};

}  // namespace lagoon::demo
