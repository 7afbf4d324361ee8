#include "physics/vehicle_motion.h"

#include <cmath>

#include "core/compass.h"

namespace lagoon::physics {
namespace {

glm::dquat yaw(double heading) {
  return glm::angleAxis(compass::angle_about_up(heading), glm::dvec3(0, 1, 0));
}

}  // namespace

glm::dquat heading_twist(const glm::dquat& q) {
  // Swing-twist decomposition about +y: the twist is q's projection onto rotations about y.
  const double n = std::sqrt(q.w * q.w + q.y * q.y);
  if (n < 1e-12) return glm::dquat(1, 0, 0, 0);  // upside down about a horizontal axis: no heading
  return glm::dquat(q.w / n, 0, q.y / n, 0);
}

VehicleMotion::VehicleMotion(std::shared_ptr<const VehicleTrack> track, FloatingBody hull)
    : route_(std::move(track)), hull_(std::move(hull)) {
  reset();
}

VehicleMotion::VehicleMotion(std::shared_ptr<const VehicleTrack> track, double depth_m)
    : route_(std::move(track)), depth_m_(depth_m) {
  reset();
}

void VehicleMotion::reset(double t0) {
  track_ = route_->at(t0);
  if (!hull_) return;
  hull_->place(glm::dvec3(track_.position.x, 0.0, track_.position.y), yaw(track_.heading));
  hull_->settle_vertically(0.0);
  hold_on(track_);
}

void VehicleMotion::hold_on(const TrackPoint& track) {
  BodyState& s = hull_->state();
  s.orientation =
      glm::normalize(yaw(track.heading) * glm::conjugate(heading_twist(s.orientation)) * s.orientation);
  const glm::dvec3 origin = hull_->model_origin();
  s.position.x += track.position.x - origin.x;
  s.position.z += track.position.y - origin.z;
  s.velocity.x = track.velocity.x;
  s.velocity.z = track.velocity.y;
  s.angular_velocity.y = -track.yaw_rate;  // the heading turns clockwise, +y counterclockwise
}

void VehicleMotion::step(double t, double dt, const WaterHeight& water, double water_top,
                         const WaterHeights& heights) {
  track_ = route_->at(t + dt);
  if (!hull_) return;
  // The path sets the horizontal motion and the heading; the water only what is left: the step sees the
  // hull at rest in those, so its damping acts on heave, pitch and roll alone.
  BodyState& s = hull_->state();
  s.velocity.x = s.velocity.z = 0;
  s.angular_velocity.y = 0;
  hull_->step(dt, water, water_top, {}, heights);
  hold_on(track_);
}

glm::dvec3 VehicleMotion::model_origin() const {
  if (hull_) return hull_->model_origin();
  return {track_.position.x, -depth_m_, track_.position.y};
}

glm::dquat VehicleMotion::orientation() const {
  return hull_ ? hull_->state().orientation : yaw(track_.heading);
}

glm::dvec3 VehicleMotion::velocity() const {
  return hull_ ? hull_->state().velocity : glm::dvec3(track_.velocity.x, 0, track_.velocity.y);
}

glm::dvec3 VehicleMotion::angular_velocity() const {
  return hull_ ? hull_->state().angular_velocity : glm::dvec3(0, -track_.yaw_rate, 0);
}

}  // namespace lagoon::physics
