// The demo's helm (issue 14): the arrow keys steer a vehicle. Up and Down change the speed ordered, which
// the vehicle reaches at a set acceleration; Left and Right put the rudder over, turning it at a rate that
// grows with its speed (a fixed turning circle at full rudder). Pure state and maths, no window: the demo
// turns key states into HelmInput and hands each changed order to the vehicle's track
// (physics/vehicle_track.h), which its body, wake and sediment all follow.
#pragma once
#include <cstddef>
#include <optional>

#include "physics/vehicle_track.h"

namespace lagoon::demo {

struct HelmInput {
  float throttle = 0;  // -1 .. 1: Down .. Up
  float rudder = 0;    // -1 .. 1: Left .. Right
};

class Helm {
 public:
  static constexpr double kMaxSpeedMps = 12;
  static constexpr double kThrottleMps2 = 3;      // the ordered speed changes this fast with a key held
  static constexpr double kAccelerationMps2 = 1;  // the vehicle's speed follows the order this fast
  static constexpr double kTurningRadiusM = 15;   // at full rudder
  static constexpr double kMaxYawRateRadps = 0.6;

  // Takes vehicles[vehicle] where it is now, at the speed it has.
  void take(size_t vehicle, const physics::TrackPoint& now);
  void release() { vehicle_.reset(); }
  std::optional<size_t> vehicle() const { return vehicle_; }

  // One frame of dt seconds with the keys in `input`: the order for the track from now on, or nothing when
  // it has not changed (a steady course adds no legs to the track).
  std::optional<physics::HelmOrder> update(HelmInput input, double dt);

  double ordered_speed() const { return ordered_; }
  double speed() const { return speed_; }
  double yaw_rate() const { return yaw_rate_; }

 private:
  std::optional<size_t> vehicle_;
  double ordered_ = 0, speed_ = 0, yaw_rate_ = 0;
  std::optional<physics::HelmOrder> last_;
};

}  // namespace lagoon::demo
