#include "helm.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lagoon::demo {

void Helm::take(size_t vehicle, const physics::TrackPoint& now) {
  vehicle_ = vehicle;
  speed_ = ordered_ = std::min(glm::length(now.velocity), kMaxSpeedMps);
  yaw_rate_ = 0;
  last_.reset();
}

std::optional<physics::HelmOrder> Helm::update(HelmInput input, double dt) {
  if (!vehicle_) return std::nullopt;
  const double throttle = std::clamp(double(input.throttle), -1.0, 1.0);
  const double rudder = std::clamp(double(input.rudder), -1.0, 1.0);
  ordered_ = std::clamp(ordered_ + throttle * kThrottleMps2 * dt, 0.0, kMaxSpeedMps);
  const double change = std::clamp(ordered_ - speed_, -kAccelerationMps2 * dt, kAccelerationMps2 * dt);
  speed_ += change;
  // A turn to starboard (right) is clockwise seen from above: the compass heading grows.
  yaw_rate_ = rudder * std::min(speed_ / kTurningRadiusM, kMaxYawRateRadps);
  const physics::HelmOrder order{speed_, yaw_rate_};
  if (last_ && last_->speed_mps == order.speed_mps && last_->yaw_rate_radps == order.yaw_rate_radps)
    return std::nullopt;
  last_ = order;
  return order;
}

}  // namespace lagoon::demo
