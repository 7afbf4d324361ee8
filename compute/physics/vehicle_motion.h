// How a vehicle moves (vehicles[], issue 14): along its track (physics/vehicle_track.h: its path at its
// speed, heading where the path goes, or where the helm orders it). At the surface its hull is a floating
// body (physics/floating_body.h) whose horizontal position and heading are held on the path while the water
// sets its heave, pitch and roll; submerged it runs level at its depth. Deterministic, stepped at a fixed
// rate like the floating bodies.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include <memory>
#include "physics/floating_body.h"

#include "physics/vehicle_track.h"

namespace lagoon::physics {

// The rotation about world +y in `q` (q = twist · swing, the swing about horizontal axes only): the
// heading of a body, without its tilt.
glm::dquat heading_twist(const glm::dquat& q);

class VehicleMotion {
 public:
  // At the surface: `hull` rides the water, held on `track` (shared with the vehicle's wake and sediment).
  VehicleMotion(std::shared_ptr<const VehicleTrack> track, FloatingBody hull);
  // Submerged: the model's origin at `depth_m` below the mean level, level, on `track`.
  VehicleMotion(std::shared_ptr<const VehicleTrack> track, double depth_m);
  VehicleMotion(WaypointPath path, FloatingBody hull)
      : VehicleMotion(std::make_shared<const VehicleTrack>(std::move(path)), std::move(hull)) {}
  VehicleMotion(WaypointPath path, double depth_m)
      : VehicleMotion(std::make_shared<const VehicleTrack>(std::move(path)), depth_m) {}

  // To time t0 (0: the path's start): where the path puts it then, at rest at its still-water draught
  // (surface) or at its depth.
  void reset(double t0 = 0.0);
  // From time t to t + dt; `water` is the sea's height at t (unused when submerged), `heights` the same for
  // a batch of points (FloatingBody::step).
  void step(double t, double dt, const WaterHeight& water,
            double water_top = std::numeric_limits<double>::infinity(), const WaterHeights& heights = {});

  glm::dvec3 model_origin() const;
  glm::dquat orientation() const;
  glm::dvec3 velocity() const;          // of the centre of mass (surface) or the origin (submerged), m/s
  glm::dvec3 angular_velocity() const;  // rad/s, world axes
  bool submerged() const { return !hull_; }
  // The hull's body (surface vehicles), or nullptr.
  const FloatingBody* hull() const { return hull_ ? &*hull_ : nullptr; }
  const VehicleTrack& track() const { return *route_; }

 private:
  // Moves the hull onto the path's point and heading, keeping its height and tilt.
  void hold_on(const TrackPoint& track);

  std::shared_ptr<const VehicleTrack> route_;
  std::optional<FloatingBody> hull_;
  double depth_m_ = 0;
  TrackPoint track_;  // where the path puts the vehicle now
};

}  // namespace lagoon::physics
