// A vehicle's track under the helm (physics/vehicle_track.h): on its path until an order, then the ordered
// speed and rate of turn, checked against a fine Runge-Kutta integration of dp/dt = v (sin h, cos h),
// dh/dt = w; continuous at each order, and the same past after a replay from an earlier time.
#include "physics/vehicle_track.h"
#include "support/reference_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace lagoon::test {
namespace {

physics::WaypointPath square_loop() {
  return physics::WaypointPath({{0, 0}, {40, 0}, {40, 40}, {0, 40}}, true, 4.0, 0.0);
}

// (x, z, heading) after `duration` at speed v and yaw rate w, by RK4 in 1 ms steps. The heading is a compass
// angle, clockwise from north (-z) toward east (+x): the velocity is v (sin h, -cos h).
glm::dvec3 integrate(glm::dvec3 s, double v, double w, double duration) {
  auto f = [v, w](glm::dvec3 y) { return glm::dvec3(v * std::sin(y.z), -v * std::cos(y.z), w); };
  const int n = int(std::round(duration / 1e-3));
  const double h = duration / n;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 k1 = f(s), k2 = f(s + 0.5 * h * k1), k3 = f(s + 0.5 * h * k2), k4 = f(s + h * k3);
    s += h / 6 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return s;
}

TEST(VehicleTrack, OnItsPathUntilOrderedThenTheOrderedArcs) {
  const physics::WaypointPath path = square_loop();
  physics::VehicleTrack track(path);
  EXPECT_FALSE(track.steered());
  for (double t : {0.0, 3.3, 17.0}) {
    EXPECT_EQ(track.at(t).position, path.at(t).position);
    EXPECT_EQ(track.at(t).heading, path.at(t).heading);
  }
  // At 5 s: a turn to starboard at 5 m/s, 0.3 rad/s; at 12 s straight on at 2 m/s; at 15 s a turn to port.
  track.order(5.0, {5.0, 0.3});
  track.order(12.0, {2.0, 0.0});
  track.order(15.0, {3.0, -0.5});
  EXPECT_EQ(track.legs(), 3u);
  const physics::TrackPoint start = path.at(5.0);
  glm::dvec3 s(start.position.x, start.position.y, start.heading);
  s = integrate(s, 5.0, 0.3, 7.0);
  const physics::TrackPoint at12 = track.at(12.0);
  EXPECT_NEAR(glm::distance(at12.position, glm::dvec2(s.x, s.y)), 0.0, 1e-6);
  EXPECT_NEAR(wrap_angle(at12.heading - s.z), 0.0, 1e-9);
  s = integrate(s, 2.0, 0.0, 3.0);
  s = integrate(s, 3.0, -0.5, 6.5);
  const physics::TrackPoint at215 = track.at(21.5);
  EXPECT_NEAR(glm::distance(at215.position, glm::dvec2(s.x, s.y)), 0.0, 1e-6);
  EXPECT_NEAR(wrap_angle(at215.heading - s.z), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(at215.velocity), 3.0, 1e-12);
  EXPECT_NEAR(at215.yaw_rate, -0.5, 1e-12);
  // Its velocity is the derivative of its position between orders, and it does not jump at them (its speed
  // may: an order is obeyed at once).
  const double e = 1e-5;
  for (double t : {8.0, 13.0, 20.0}) {
    const glm::dvec2 rate = (track.at(t + e).position - track.at(t - e).position) / (2 * e);
    EXPECT_NEAR(glm::distance(rate, track.at(t).velocity), 0.0, 1e-4) << "t = " << t;
  }
  for (double t : {5.0, 12.0, 15.0})
    EXPECT_NEAR(glm::distance(track.at(t + e).position, track.at(t - e).position), 0.0, 1e-4) << "t = " << t;
}

TEST(VehicleTrack, AnOrderForAnEarlierTimeReplaysFromThere) {
  physics::VehicleTrack a(square_loop()), b(square_loop());
  a.order(5.0, {5.0, 0.3});
  a.order(9.0, {1.0, -0.2});
  const glm::dvec2 before = a.at(7.0).position;
  a.order(8.0, {5.0, 0.0});  // drops the order at 9 s
  EXPECT_EQ(a.legs(), 2u);
  b.order(5.0, {5.0, 0.3});
  b.order(8.0, {5.0, 0.0});
  EXPECT_EQ(a.at(7.0).position, before) << "the past before the new order is kept";
  for (double t : {8.0, 9.5, 30.0}) EXPECT_EQ(a.at(t).position, b.at(t).position);
}

TEST(VehicleTrack, AFullCircleComesBackToItsStart) {
  // 2π / w seconds of a constant turn: back where it started, heading as it started (radius v / w).
  physics::VehicleTrack track(physics::WaypointPath({{3, 4}, {3, 50}}, false, 2.0, 0.0));
  track.order(1.0, {6.0, 0.4});
  const physics::TrackPoint start = track.at(1.0);
  const physics::TrackPoint end = track.at(1.0 + 2 * std::numbers::pi / 0.4);
  EXPECT_NEAR(glm::distance(start.position, end.position), 0.0, 1e-9);
  EXPECT_NEAR(wrap_angle(start.heading - end.heading), 0.0, 1e-9);
  // Half way round it is a diameter, 2 v / w, away; turning to starboard (+0.4 rad/s, clockwise seen from
  // above) from heading south (+z) it went west, towards -x.
  const physics::TrackPoint half = track.at(1.0 + std::numbers::pi / 0.4);
  EXPECT_NEAR(glm::distance(start.position, half.position), 2 * 6.0 / 0.4, 1e-9);
  EXPECT_LT(half.position.x, start.position.x - 29.0);
}

TEST(VehicleTrack, APlacedVehicleRunsFromWhereItWasPutAndKeepsItsPast) {
  // An external controller puts the vehicle at (10, -20), heading east (pi/2), at 8 s, turning to starboard
  // at 3 m/s and 0.2 rad/s: from then on the ordered arc from there (RK4), before then its path.
  const physics::WaypointPath path = square_loop();
  physics::VehicleTrack track(path);
  track.order(4.0, {5.0, 0.1});
  track.order(9.0, {1.0, 0.0});  // dropped by the placement at 8 s
  const glm::dvec2 before = track.at(6.0).position;
  physics::TrackPoint where;
  where.position = {10.0, -20.0};
  where.heading = std::numbers::pi / 2 + 2 * std::numbers::pi;  // wrapped
  track.place(8.0, where, {3.0, 0.2});
  EXPECT_EQ(track.legs(), 2u);
  EXPECT_EQ(track.at(6.0).position, before);
  const physics::TrackPoint at8 = track.at(8.0);
  EXPECT_NEAR(glm::distance(at8.position, where.position), 0.0, 1e-12);
  EXPECT_NEAR(at8.heading, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(glm::distance(at8.velocity, glm::dvec2(3.0, 0.0)), 0.0, 1e-12);  // east is +x
  const glm::dvec3 s = integrate(glm::dvec3(10.0, -20.0, std::numbers::pi / 2), 3.0, 0.2, 4.5);
  const physics::TrackPoint later = track.at(12.5);
  EXPECT_NEAR(glm::distance(later.position, glm::dvec2(s.x, s.y)), 0.0, 1e-6);
  EXPECT_NEAR(wrap_angle(later.heading - s.z), 0.0, 1e-9);
  // An order at the placement's own time starts from the placed point (a controller that places, then
  // steers, in one step), not from where the path had it.
  track.order(8.0, {2.0, 0.0});
  EXPECT_NEAR(glm::distance(track.at(10.0).position, glm::dvec2(14.0, -20.0)), 0.0, 1e-9);
}

}  // namespace
}  // namespace lagoon::test
