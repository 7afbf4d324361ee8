// Vehicles (vehicles[], issue 14): the path's geometry against its waypoints and its speed, and the motion:
// held on the path and heading, with heave, pitch and roll left to the water at the surface, and level at
// its depth when submerged.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

#include "physics/vehicle_motion.h"
#include "physics/waypoint_path.h"
#include "support/box_mesh.h"
#include "support/reference_math.h"

namespace lagoon::test {
namespace {

// The angle of the rotation between two orientations.
double angle_between(const glm::dquat& a, const glm::dquat& b) {
  return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(a, b))));
}

// A model facing +z turned to a compass heading (clockwise from north, -z): Ry(π - heading) takes +z to
// (sin h, 0, -cos h).
glm::dquat yaw(double heading) {
  return glm::angleAxis(std::numbers::pi - heading, glm::dvec3(0, 1, 0));
}

physics::WaypointPath square_loop(double speed) {
  return physics::WaypointPath({{0, 0}, {40, 0}, {40, 40}, {0, 40}}, true, speed, 0.0);
}

TEST(WaypointPath, StraightOpenPathAtConstantSpeedThenStops) {
  const physics::WaypointPath path({{0, 0}, {30, 40}}, false, 5.0, 0.0);
  EXPECT_NEAR(path.length(), 50.0, 1e-6);
  const physics::TrackPoint p = path.at(2.0);
  EXPECT_NEAR(p.position.x, 6.0, 1e-6);
  EXPECT_NEAR(p.position.y, 8.0, 1e-6);
  // Toward +x (east) and +z (south): a compass heading of 180° - atan(30/40) = 143.13°.
  EXPECT_NEAR(p.heading, std::numbers::pi - std::atan2(30.0, 40.0), 1e-6);
  EXPECT_NEAR(p.velocity.x, 3.0, 1e-6);
  EXPECT_NEAR(p.velocity.y, 4.0, 1e-6);
  const physics::TrackPoint end = path.at(20.0);  // 100 m of travel on a 50 m path
  EXPECT_NEAR(glm::distance(end.position, glm::dvec2(30, 40)), 0.0, 1e-6);
  EXPECT_EQ(end.velocity, glm::dvec2(0.0));
  // start_m starts it further along.
  const physics::WaypointPath later({{0, 0}, {30, 40}}, false, 5.0, 25.0);
  EXPECT_NEAR(glm::distance(later.at(0.0).position, glm::dvec2(15, 20)), 0.0, 1e-6);
}

TEST(WaypointPath, ClosedLoopPassesEveryWaypointAtConstantSpeedWithASmoothHeading) {
  const double speed = 4.0, dt = 0.01;
  const physics::WaypointPath path = square_loop(speed);
  // A curve through the corners of a 40 m square is longer than the square's diagonal tour and shorter than
  // a circle around it.
  EXPECT_GT(path.length(), 150.0);
  EXPECT_LT(path.length(), std::numbers::pi * 40.0 * std::sqrt(2.0));
  const double period = path.length() / speed;
  double nearest[4] = {1e9, 1e9, 1e9, 1e9};
  const glm::dvec2 corners[4] = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  physics::TrackPoint last = path.at(0.0);
  for (double t = dt; t < 2 * period; t += dt) {
    const physics::TrackPoint p = path.at(t);
    for (int c = 0; c < 4; ++c) nearest[c] = std::min(nearest[c], glm::distance(p.position, corners[c]));
    const glm::dvec2 moved = p.position - last.position;
    ASSERT_NEAR(glm::length(moved) / dt, speed, 0.01 * speed) << "t = " << t;
    // The heading is the direction of travel (a compass angle, clockwise from north = -z), and it turns
    // without jumps (also where the loop closes).
    const double travel = std::atan2(moved.x, -moved.y);
    ASSERT_LT(std::abs(wrap_angle(travel - last.heading - 0.5 * wrap_angle(p.heading - last.heading))), 0.02)
        << "t = " << t;
    ASSERT_LT(std::abs(wrap_angle(p.heading - last.heading)), 0.05) << "t = " << t;
    // The yaw rate is the heading's rate of change.
    ASSERT_NEAR(0.5 * (p.yaw_rate + last.yaw_rate), wrap_angle(p.heading - last.heading) / dt, 0.05)
        << "t = " << t;
    last = p;
  }
  for (int c = 0; c < 4; ++c) EXPECT_LT(nearest[c], speed * dt) << "corner " << c;
  // After one period it is back where it started.
  EXPECT_NEAR(glm::distance(path.at(period).position, path.at(0.0).position), 0.0, 1e-6);
}

TEST(VehicleMotion, HeadingTwistIsTheYawOfATiltedPose) {
  for (double heading : {-2.5, -0.3, 0.0, 1.0, 3.0}) {
    const glm::dquat tilt = glm::angleAxis(0.2, glm::normalize(glm::dvec3(1, 0, 0.5)));
    const glm::dquat twist = physics::heading_twist(yaw(heading) * tilt);
    EXPECT_LT(angle_between(twist, yaw(heading)), 1e-6) << heading;
  }
}

// A 4 m long, 1.6 m wide, 1 m high box of half the water's density: it floats half under, its origin (the
// box's centre) on the water.
physics::FloatingBody half_density_box() {
  const physics::TriangleMesh hull = box({0.8, 0.5, 2.0});
  return physics::FloatingBody(hull, physics::solid_mass_properties(hull, 1025.0 / 2), {}, {});
}

TEST(VehicleMotion, SurfaceVehicleRidesAtItsDraughtOnThePathAndHeading) {
  physics::VehicleMotion motion(square_loop(3.0), half_density_box());
  const physics::WaterHeight calm = [](double, double) { return 0.0; };
  const double dt = 1.0 / 120.0;
  for (int k = 0; k < 120 * 60; ++k) {  // a minute: more than a lap, through all four turns
    const double t = k * dt;
    motion.step(t, dt, calm);
    const physics::TrackPoint track = motion.track().at(t + dt);
    const glm::dvec3 origin = motion.model_origin();
    ASSERT_NEAR(origin.x, track.position.x, 1e-9) << "t = " << t;
    ASSERT_NEAR(origin.z, track.position.y, 1e-9) << "t = " << t;
    ASSERT_NEAR(origin.y, 0.0, 0.02 * 1.0) << "t = " << t;  // half of its 1 m height under
    ASSERT_LT(angle_between(motion.orientation(), yaw(track.heading)), 0.01) << "t = " << t;
    ASSERT_NEAR(glm::length(motion.velocity()), 3.0, 1e-6) << "t = " << t;
    // Its bow (+z) points where it goes.
    const glm::dvec3 bow = motion.orientation() * glm::dvec3(0, 0, 1);
    ASSERT_LT(glm::distance(glm::normalize(glm::dvec2(bow.x, bow.z)), glm::normalize(track.velocity)), 0.02)
        << "t = " << t;
  }
}

TEST(VehicleMotion, SurfaceVehicleFollowsTheWaterUpAndDown) {
  physics::VehicleMotion motion(physics::WaypointPath({{0, 0}, {100, 0}}, false, 2.0, 0.0),
                                half_density_box());
  const physics::WaterHeight raised = [](double, double) { return 0.4; };
  const double dt = 1.0 / 120.0;
  // Lifted 0.4 m at once, it bobs (lightly damped, like the floating bodies) and settles on the new level.
  for (int k = 0; k < 120 * 40; ++k) motion.step(k * dt, dt, raised);
  EXPECT_NEAR(motion.model_origin().y, 0.4, 0.02);
  EXPECT_NEAR(motion.velocity().y, 0.0, 0.02);
}

TEST(VehicleMotion, SubmergedVehicleRunsLevelAtItsDepth) {
  physics::VehicleMotion motion(square_loop(1.5), 6.0);
  EXPECT_TRUE(motion.submerged());
  const physics::WaterHeight unused = [](double, double) { return 100.0; };
  for (int k = 0; k < 600; ++k) {
    const double t = k / 120.0;
    motion.step(t, 1.0 / 120.0, unused);
    const physics::TrackPoint track = motion.track().at(t + 1.0 / 120.0);
    ASSERT_NEAR(glm::distance(motion.model_origin(), glm::dvec3(track.position.x, -6.0, track.position.y)),
                0.0, 1e-12);
    ASSERT_LT(angle_between(motion.orientation(), yaw(track.heading)), 1e-6);
  }
}

}  // namespace
}  // namespace lagoon::test
