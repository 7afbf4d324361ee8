// Floating bodies (compute/physics, issue 14): mass properties against a box's closed form, the water's
// pressure against Archimedes, and the motion: a half-density box floats at half its height and settles, a
// drop comes to rest, an hour stays finite, and a small body heaves with a long regular wave.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

#include "physics/floating_body.h"
#include "physics/hydrostatics.h"
#include "physics/mass_properties.h"
#include "support/box_mesh.h"
#include "support/reference_math.h"

namespace lagoon::test {
namespace {

constexpr double kRhoWater = 1025.0;

physics::WaterHeight flat(double level = 0.0) {
  return [level](double, double) { return level; };
}

TEST(MassProperties, BoxMatchesTheClosedForm) {
  const glm::dvec3 h(1.0, 0.3, 0.5), c(2.0, -1.0, 0.5);
  const physics::MassProperties m = physics::solid_mass_properties(box(h, c), 500.0);
  const double volume = 8 * h.x * h.y * h.z, mass = 500.0 * volume;
  EXPECT_NEAR(m.volume, volume, 1e-12);
  EXPECT_NEAR(m.mass, mass, 1e-9);
  EXPECT_NEAR(glm::length(m.centre - c), 0.0, 1e-12);
  // I_xx = m(b² + c²)/3 for half-extents (a, b, c); no products of inertia along the box's axes.
  EXPECT_NEAR(m.inertia[0][0], mass * (h.y * h.y + h.z * h.z) / 3, 1e-9);
  EXPECT_NEAR(m.inertia[1][1], mass * (h.x * h.x + h.z * h.z) / 3, 1e-9);
  EXPECT_NEAR(m.inertia[2][2], mass * (h.x * h.x + h.y * h.y) / 3, 1e-9);
  EXPECT_NEAR(m.inertia[0][1], 0.0, 1e-9);
  EXPECT_NEAR(m.inertia[1][2], 0.0, 1e-9);
}

TEST(Hydrostatics, ArchimedesAndTheCentreOfBuoyancy) {
  const glm::dvec3 h(1.0, 0.3, 0.5);
  const physics::TriangleMesh b = box(h);
  const double volume = 8 * h.x * h.y * h.z;
  // Fully under: ρgV upwards, no torque about the centre.
  physics::Wrench w = physics::hydrostatic_wrench(b.vertices, b.indices, flat(5.0), {}, kRhoWater, kG);
  EXPECT_NEAR(w.force.y, kRhoWater * kG * volume, 1e-6 * kRhoWater * kG * volume);
  EXPECT_NEAR(glm::length(glm::dvec2(w.force.x, w.force.z)), 0.0, 1e-6);
  EXPECT_NEAR(glm::length(w.torque), 0.0, 1e-6);
  // Half under: half the force, acting at the submerged half's centre (0, -h.y/2, 0); about (1, 0, 0) that
  // is a lever of (-1, -h.y/2, 0): τ = r × F = (0, 0, -F).
  w = physics::hydrostatic_wrench(b.vertices, b.indices, flat(0.0), glm::dvec3(1, 0, 0), kRhoWater, kG);
  const double half = kRhoWater * kG * volume / 2;
  EXPECT_NEAR(w.force.y, half, 1e-9 * half);
  EXPECT_NEAR(w.torque.z, -half, 1e-9 * half);
  EXPECT_NEAR(w.torque.x, 0.0, 1e-6);
  // A quarter under, water sloping along x (depth linear): the force is ρg times the wedge's volume.
  w = physics::hydrostatic_wrench(
      b.vertices, b.indices, [](double x, double) { return -0.15 + 0.1 * x; }, {}, kRhoWater, kG);
  // Wedge: depth below the surface y = -0.15 + 0.1x over the box's bottom at -0.3: (0.15 + 0.1x) over x in
  // [-1, 1] times the z extent 1 m, the surface within the box's sides everywhere.
  EXPECT_NEAR(w.force.y, kRhoWater * kG * (0.15 * 2.0) * 1.0, 1e-6 * kRhoWater * kG);
}

physics::FloatingBody half_density_box(glm::dvec3 h, physics::Damping damping = {}) {
  const physics::TriangleMesh hull = box(h);
  return physics::FloatingBody(hull, physics::solid_mass_properties(hull, kRhoWater / 2), damping,
                               physics::WaterProperties{kRhoWater, kG});
}

TEST(FloatingBody, HalfDensityBoxFloatsAtHalfItsHeightAndSettles) {
  const glm::dvec3 h(0.5, 0.3, 0.5);
  physics::FloatingBody body = half_density_box(h);
  body.place(glm::dvec3(0, h.y, 0), glm::dquat(1, 0, 0, 0));  // bottom on the water
  for (int i = 0; i < 60 * 120; ++i) body.step(1.0 / 120, flat());
  // Half its height under the water: the centre at the waterline, within 2 % of the height.
  EXPECT_NEAR(body.state().position.y, 0.0, 0.02 * 2 * h.y);
  EXPECT_LT(glm::length(body.state().velocity), 1e-3);
  RecordProperty("centre_y", std::to_string(body.state().position.y));
}

TEST(FloatingBody, SettlesVerticallyToItsDraughtInStillWater) {
  // A half-density box tilted 30° about z still floats with half its volume under: its centre at the level
  // (symmetric about its centre, so half under means centre on the waterline).
  const glm::dvec3 h(0.5, 0.3, 0.5);
  physics::FloatingBody body = half_density_box(h);
  body.place(glm::dvec3(1, 5, 2), glm::angleAxis(0.5236, glm::dvec3(0, 0, 1)));
  ASSERT_TRUE(body.settle_vertically(0.25));
  EXPECT_NEAR(body.state().position.y, 0.25, 1e-6);
  EXPECT_NEAR(body.state().position.x, 1.0, 1e-12);
  body.step(1.0 / 120, flat(0.25));
  EXPECT_NEAR(body.state().velocity.y, 0.0, 1e-6) << "it was not at rest";
  // Twice water's density: it cannot float and stays where it was put.
  const physics::TriangleMesh hull = box(h);
  physics::FloatingBody stone(hull, physics::solid_mass_properties(hull, 2 * kRhoWater), {}, {});
  stone.place(glm::dvec3(0, 3, 0), glm::dquat(1, 0, 0, 0));
  EXPECT_FALSE(stone.settle_vertically(0.0));
  EXPECT_EQ(stone.state().position.y, 3.0);
}

TEST(FloatingBody, ADropFromOneMetreComesToRest) {
  const glm::dvec3 h(0.5, 0.3, 0.5);
  physics::FloatingBody body = half_density_box(h);
  body.place(glm::dvec3(0, 1.0, 0), glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 0, 1))));
  double highest = 0, deepest = 0;
  for (int i = 0; i < 120 * 120; ++i) {
    body.step(1.0 / 120, flat());
    highest = std::max(highest, body.state().position.y);
    deepest = std::min(deepest, body.state().position.y);
  }
  EXPECT_LE(highest, 1.0 + 1e-9) << "it gained energy";
  EXPECT_GT(deepest, -1.5) << "it sank or blew up";
  EXPECT_NEAR(body.state().position.y, 0.0, 0.02 * 2 * h.y);
  EXPECT_LT(body.kinetic_energy(), 1e-6);
  // Upright again: a flat box floats flat.
  EXPECT_GT(std::abs((body.state().orientation * glm::dvec3(0, 1, 0)).y), 0.999);
}

TEST(FloatingBody, AnHourStaysFiniteAndItsEnergyBounded) {
  const glm::dvec3 h(0.5, 0.3, 0.5);
  physics::FloatingBody body =
      half_density_box(h, {.linear = 0.05, .quadratic = 0.05, .angular = 0.05, .angular_quadratic = 0.05});
  body.place(glm::dvec3(0, 1.0, 0), glm::angleAxis(0.6, glm::normalize(glm::dvec3(1, 0.2, 1))));
  const double bound = body.mass().mass * kG * (1.0 + 2 * h.y);  // all the potential energy it can release
  double most = 0;
  bool finite = true;
  for (int i = 0; i < 3600 * 120; ++i) {
    // A slow swell, so it never quite rests.
    const double t = i / 120.0;
    body.step(1.0 / 120, [t](double x, double) { return 0.2 * std::cos(0.1 * x - std::sqrt(kG * 0.1) * t); });
    most = std::max(most, body.kinetic_energy());
    finite = finite && std::isfinite(body.state().position.y) && std::isfinite(body.state().orientation.w);
  }
  EXPECT_TRUE(finite);
  EXPECT_LT(most, bound);
  RecordProperty("most_kinetic_J", std::to_string(most));
}

TEST(FloatingBody, HeavesWithALongRegularWave) {
  // A 1 m box, 0.4 m tall, in a 60 m wave 0.3 m high (deep water: ω² = gk, T = 6.2 s). Its heave
  // resonance (ω0² = 2g/height, 7 rad/s) is far above the wave's 1 rad/s, so it follows the surface:
  // amplitude 1/(1 - (ω/ω0)²) = 1.02 of the wave's, in phase.
  const double amplitude = 0.3, k = 2 * std::numbers::pi / 60.0, omega = std::sqrt(kG * k);
  physics::FloatingBody body = half_density_box(glm::dvec3(0.5, 0.2, 0.5));
  body.place(glm::dvec3(0, amplitude, 0), glm::dquat(1, 0, 0, 0));
  const double dt = 1.0 / 120, period = 2 * std::numbers::pi / omega;
  const int settle = int(10 * period / dt), measure = int(10 * period / dt);
  double a = 0, b = 0, mean = 0;
  std::vector<std::pair<double, double>> samples;  // (body y, wave phase at the body)
  for (int i = 0; i < settle + measure; ++i) {
    const double t = i * dt;
    body.step(dt, [&](double x, double) { return amplitude * std::cos(k * x - omega * t); });
    if (i < settle) continue;
    const double theta = k * body.state().position.x - omega * (t + dt);
    samples.push_back({body.state().position.y, theta});
    mean += body.state().position.y;
  }
  mean /= samples.size();
  for (const auto& [y, theta] : samples) {
    a += 2.0 * (y - mean) * std::cos(theta) / samples.size();
    b += 2.0 * (y - mean) * std::sin(theta) / samples.size();
  }
  const double heave = std::hypot(a, b), phase_deg = std::atan2(b, a) * 180.0 / std::numbers::pi;
  RecordProperty("heave_over_amplitude", std::to_string(heave / amplitude));
  RecordProperty("phase_deg", std::to_string(phase_deg));
  EXPECT_NEAR(heave, amplitude, 0.1 * amplitude);
  EXPECT_NEAR(phase_deg, 0.0, 15.0);
}

}  // namespace
}  // namespace lagoon::test
