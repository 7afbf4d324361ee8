// How a vehicle moves (vehicles[], issue 14): along its path (physics/waypoint_path.h) at its speed,
// heading where the path goes. At the surface its hull is a floating body (physics/floating_body.h) whose
// horizontal position and heading are held on the path while the water sets its heave, pitch and roll;
// submerged it runs level at its depth. Deterministic, stepped at a fixed rate like the floating bodies.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "physics/floating_body.h"
#include "physics/waypoint_path.h"

namespace lagoon::physics {

// The rotation about world +y in `q` (q = twist · swing, the swing about horizontal axes only): the
// heading of a body, without its tilt.
glm::dquat heading_twist(const glm::dquat& q);

class VehicleMotion {
 public:
  // At the surface: `hull` rides the water, held on `path`.
  VehicleMotion(WaypointPath path, FloatingBody hull);
  // Submerged: the model's origin at `depth_m` below the mean level, level, on `path`.
  VehicleMotion(WaypointPath path, double depth_m);

  // To time 0: on the path's start, at rest at its still-water draught (surface) or at its depth.
  void reset();
  // From time t to t + dt; `water` is the sea's height at t (unused when submerged).
  void step(double t, double dt, const WaterHeight& water);

  glm::dvec3 model_origin() const;
  glm::dquat orientation() const;
  glm::dvec3 velocity() const;          // of the centre of mass (surface) or the origin (submerged), m/s
  glm::dvec3 angular_velocity() const;  // rad/s, world axes
  bool submerged() const { return !hull_; }
  // The hull's body (surface vehicles), or nullptr.
  const FloatingBody* hull() const { return hull_ ? &*hull_ : nullptr; }
  const WaypointPath& path() const { return path_; }

 private:
  // Moves the hull onto the path's point and heading, keeping its height and tilt.
  void hold_on(const TrackPoint& track);

  WaypointPath path_;
  std::optional<FloatingBody> hull_;
  double depth_m_ = 0;
  TrackPoint track_;  // where the path puts the vehicle now
};

}  // namespace lagoon::physics
