// Floating bodies (compute/physics, issue 14): mass properties against a box's closed form, the water's
// pressure against Archimedes, and the motion: a half-density box floats at half its height and settles, a
// drop comes to rest, an hour stays finite, and a small body heaves with a long regular wave. Issue 33: the
// heave in a wave as long as the body follows Froude–Krylov's sinc law whatever the model's tessellation,
// and bodies rest on a floor (flat or sloping) or rise off it.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "physics/floating_body.h"
#include "physics/hydrostatics.h"
#include "physics/mass_properties.h"
#include "physics/mesh_floor.h"
#include "physics/sphere_mesh.h"
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

// The water's upper bound only spares lookups: a hull poking out of a wavy surface gets the same wrench
// with a true bound, asks for fewer heights, and a bound below the real water (a wrong one) changes it, so
// the comparison can fail.
TEST(Hydrostatics, ABoundOnTheWaterSparesTheDryHullsLookupsAndNothingElse) {
  const physics::TriangleMesh fine = physics::refine_hull(box({1.0, 2.0, 0.5}), {.spacing_m = 0.1});
  int lookups = 0;
  const physics::WaterHeight wavy = [&lookups](double x, double z) {
    ++lookups;
    return 0.2 * std::sin(1.3 * x) + 0.1 * std::cos(2.1 * z);  // at most 0.3
  };
  const physics::Wrench all =
      physics::hydrostatic_wrench(fine.vertices, fine.indices, wavy, {}, kRhoWater, kG);
  const int every = lookups;
  lookups = 0;
  const physics::Wrench bounded =
      physics::hydrostatic_wrench(fine.vertices, fine.indices, wavy, {}, kRhoWater, kG, 0.3);
  EXPECT_EQ(bounded.force, all.force);
  EXPECT_EQ(bounded.torque, all.torque);
  EXPECT_EQ(bounded.wetted_area, all.wetted_area);
  EXPECT_LT(lookups, 0.7 * every) << "the hull's top 1.7 m is dry";
  RecordProperty("lookups", std::to_string(lookups) + " of " + std::to_string(every));
  const physics::Wrench wrong =
      physics::hydrostatic_wrench(fine.vertices, fine.indices, wavy, {}, kRhoWater, kG, -0.1);
  // The skipped wet strip is on the vertical sides: it carries no vertical force, but its area and its
  // horizontal pressure go missing.
  EXPECT_LT(wrong.wetted_area, all.wetted_area - 0.1);
}

// HullPressure is hydrostatic_wrench with the body-frame parts computed once: for a tilted, turned hull
// cutting a wavy surface (wholly wet, cut and dry triangles) it must give hydrostatic_wrench's force, torque
// and wetted area about the centre, asked point by point, in a batch or through a pressure head.
TEST(Hydrostatics, AHullsPrecomputedPressureGivesTheWrenchOfItsTriangles) {
  const physics::TriangleMesh fine = physics::refine_hull(box({1.0, 0.6, 0.5}), {.spacing_m = 0.15});
  const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(0.4, glm::normalize(glm::dvec3(0.3, 1.0, 0.5))));
  const glm::dvec3 centre(2.0, -0.2, -1.0);
  std::vector<glm::dvec3> world;
  for (const glm::dvec3& v : fine.vertices) world.push_back(centre + turn * v);
  const physics::WaterHeight wavy = [](double x, double z) {
    return 0.2 * std::sin(1.3 * x) + 0.1 * std::cos(2.1 * z);
  };
  const physics::WaterHeights batch = [&wavy](std::span<const glm::dvec2> p, std::span<double> h) {
    for (size_t i = 0; i < p.size(); ++i) h[i] = wavy(p[i].x, p[i].y);
  };
  const physics::PressureHead head = [&wavy](double x, double y, double z) {
    return y + 0.5 * (wavy(x, z) - y);  // any head: both paths must ask it alike
  };
  const physics::Wrench reference =
      physics::hydrostatic_wrench(world, fine.indices, wavy, centre, kRhoWater, kG);
  const physics::Wrench reference_head =
      physics::hydrostatic_wrench(world, fine.indices, wavy, centre, kRhoWater, kG, 1e300, head);
  ASSERT_GT(reference.wetted_area, 1.0);
  ASSERT_LT(reference.wetted_area, 0.9 * 2 * (1.2 * 0.6 + 1.2 * 2.0 + 0.6 * 2.0)) << "the hull must be cut";
  ASSERT_GT(glm::length(reference.torque), 100.0) << "a tilted hull in waves feels a torque";
  physics::HullPressure pressure(fine.vertices, fine.indices);
  auto expect_same = [](const physics::Wrench& got, const physics::Wrench& want, const char* how) {
    const double f = glm::length(want.force), t = glm::length(want.torque);
    EXPECT_LT(glm::length(got.force - want.force), 1e-9 * f) << how;
    EXPECT_LT(glm::length(got.torque - want.torque), 1e-9 * (t + f)) << how;
    EXPECT_NEAR(got.wetted_area, want.wetted_area, 1e-12 * want.wetted_area) << how;
  };
  expect_same(pressure.wrench(world, turn, centre, {.height = &wavy}, kRhoWater, kG), reference, "height");
  expect_same(
      pressure.wrench(world, turn, centre, {.height = &wavy, .heights = &batch, .top = 0.3}, kRhoWater, kG),
      reference, "batch");
  expect_same(pressure.wrench(world, turn, centre, {.height = &wavy, .head = &head}, kRhoWater, kG),
              reference_head, "head");
}

physics::FloatingBody half_density_box(glm::dvec3 h, physics::Damping damping = {},
                                       physics::HullSampling sampling = {}) {
  const physics::TriangleMesh hull = box(h);
  return physics::FloatingBody(hull, physics::solid_mass_properties(hull, kRhoWater / 2), damping,
                               physics::WaterProperties{kRhoWater, kG}, {.sampling = sampling});
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
  // Sampled every 0.25 m (not the default 1/16 of its size): the swell is 63 m long, and an hour at the
  // default's 3000 triangles would take a minute.
  physics::FloatingBody body =
      half_density_box(h, {.linear = 0.05, .quadratic = 0.05, .angular = 0.05, .angular_quadratic = 0.05},
                       {.spacing_m = 0.25});
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

// Heave amplitude (m) of a body in the regular wave h = a·cos(kx − ωt), deep water (ω² = gk), fitted at the
// wave's frequency over `measure` periods after `settle` periods of transients.
double heave_in_wave(physics::FloatingBody& body, double amplitude, double length_m, int settle = 10,
                     int measure = 6) {
  const double k = 2 * std::numbers::pi / length_m, omega = std::sqrt(kG * k);
  const double dt = 1.0 / 120, period = 2 * std::numbers::pi / omega;
  const int first = int(settle * period / dt), steps = first + int(measure * period / dt);
  std::vector<std::pair<double, double>> samples;  // (body y, wave phase at the body)
  double mean = 0;
  for (int i = 0; i < steps; ++i) {
    const double t = i * dt;
    body.step(dt, [&](double x, double) { return amplitude * std::cos(k * x - omega * t); });
    if (i < first) continue;
    samples.push_back({body.state().position.y, k * body.state().position.x - omega * (t + dt)});
    mean += body.state().position.y / double(steps - first);
  }
  double a = 0, b = 0;
  for (const auto& [y, theta] : samples) {
    a += 2.0 * (y - mean) * std::cos(theta) / double(samples.size());
    b += 2.0 * (y - mean) * std::sin(theta) / double(samples.size());
  }
  return std::hypot(a, b);
}

// A box 2h long (x), of half water's density, with n x n quads a face, floating level in still water.
physics::FloatingBody tessellated_half_density_box(glm::dvec3 h, int n, physics::HullSampling sampling = {}) {
  const physics::TriangleMesh hull = tessellated_box(h, n);
  physics::FloatingBody body(hull, physics::solid_mass_properties(hull, kRhoWater / 2), {},
                             physics::WaterProperties{kRhoWater, kG}, {.sampling = sampling});
  body.place(glm::dvec3(0.0), glm::dquat(1, 0, 0, 0));
  return body;
}

TEST(HullSampling, RefiningKeepsTheSurfaceAndItsBuoyancy) {
  const glm::dvec3 h(5.0, 0.1, 1.0);
  const physics::TriangleMesh hull = box(h);
  const physics::TriangleMesh fine = physics::refine_hull(hull, {});
  const double spacing = physics::sample_spacing(hull, {});
  EXPECT_NEAR(spacing, 10.0 / 16, 1e-12);
  double longest = 0;
  for (size_t t = 0; t < fine.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, glm::distance(fine.vertices[fine.indices[t + k]],
                                                fine.vertices[fine.indices[t + (k + 1) % 3]]));
  EXPECT_LE(longest, spacing + 1e-12);
  EXPECT_NEAR(physics::solid_mass_properties(fine, 1.0).volume, 8 * h.x * h.y * h.z, 1e-9);
  const physics::Wrench w =
      physics::hydrostatic_wrench(fine.vertices, fine.indices, flat(), {}, kRhoWater, kG);
  EXPECT_NEAR(w.force.y, kRhoWater * kG * 4 * h.x * h.y * h.z, 1e-6 * kRhoWater * kG);
  // The cap raises the spacing; a negative spacing keeps the model's own triangles.
  EXPECT_LE(physics::refine_hull(hull, {.max_triangles = 500}).indices.size() / 3, 500u);
  EXPECT_EQ(physics::refine_hull(hull, {.spacing_m = -1}).indices.size(), hull.indices.size());
  RecordProperty("refined_triangles", std::to_string(fine.indices.size() / 3));
}

// A 10 m x 2 m x 0.2 m box of half water's density in a 20 m wave 5 cm high. Quasi-static Froude–Krylov:
// the pressure averaged over its length is sinc(kL/2) of the wave's (0.637 at kL/2 = π/2), and its heave
// resonance (ω_n² = ρgA_wp/m = g/draught, no added mass) lifts that by 1/(1 − (ω/ω_n)²): 0.657 of the wave.
// The model's tessellation (2 or 800 triangles a face) must not matter.
TEST(FloatingBody, HeaveFollowsTheSincLawWhateverTheTessellation) {
  const glm::dvec3 h(5.0, 0.1, 1.0);
  const double amplitude = 0.05, length = 20.0, k = 2 * std::numbers::pi / length;
  const double omega2 = kG * k, omega_n2 = kG / h.y;  // draught h.y at half density
  const double expected = std::sin(k * h.x) / (k * h.x) / (1 - omega2 / omega_n2);
  physics::FloatingBody coarse = tessellated_half_density_box(h, 1);
  physics::FloatingBody fine = tessellated_half_density_box(h, 20);
  const double coarse_ratio = heave_in_wave(coarse, amplitude, length) / amplitude;
  const double fine_ratio = heave_in_wave(fine, amplitude, length) / amplitude;
  RecordProperty("expected", std::to_string(expected));
  RecordProperty("coarse_heave_over_amplitude", std::to_string(coarse_ratio));
  RecordProperty("fine_heave_over_amplitude", std::to_string(fine_ratio));
  EXPECT_NEAR(coarse_ratio, expected, 0.1 * expected);
  EXPECT_NEAR(fine_ratio, expected, 0.1 * expected);
  EXPECT_NEAR(coarse_ratio, fine_ratio, 0.02 * fine_ratio);
}

// As long as the wave (kL/2 = π): the wave's pressure cancels along it, so it hardly heaves.
TEST(FloatingBody, ABoxAsLongAsTheWaveHardlyHeaves) {
  const glm::dvec3 h(10.0, 0.1, 1.0);
  const double amplitude = 0.05;
  for (int n : {1, 20}) {
    physics::FloatingBody body = tessellated_half_density_box(h, n);
    const double ratio = heave_in_wave(body, amplitude, 20.0) / amplitude;
    RecordProperty("heave_over_amplitude_n" + std::to_string(n), std::to_string(ratio));
    EXPECT_LT(ratio, 0.1) << n << " x " << n << " quads a face";
  }
}

// Without refinement (the water sampled at the model's vertices only) the same box heaves as its modeller
// tessellated it: the two-triangle box sees the wave at its ends only, in antiphase.
TEST(FloatingBody, AtTheModelsVerticesOnlyTheHeaveDependsOnTessellation) {
  const glm::dvec3 h(5.0, 0.1, 1.0);
  const double amplitude = 0.05;
  physics::FloatingBody coarse = tessellated_half_density_box(h, 1, {.spacing_m = -1});
  physics::FloatingBody fine = tessellated_half_density_box(h, 20, {.spacing_m = -1});
  const double coarse_ratio = heave_in_wave(coarse, amplitude, 20.0) / amplitude;
  const double fine_ratio = heave_in_wave(fine, amplitude, 20.0) / amplitude;
  RecordProperty("coarse_heave_over_amplitude", std::to_string(coarse_ratio));
  RecordProperty("fine_heave_over_amplitude", std::to_string(fine_ratio));
  EXPECT_LT(coarse_ratio, 0.5 * fine_ratio);
}

// A body on a floor at y_floor(x, z), released level at `y` and run `seconds`.
physics::FloatingBody on_floor(double density, physics::FloorHeight floor, glm::dvec3 at, double seconds,
                               glm::dquat orientation = glm::dquat(1, 0, 0, 0)) {
  const physics::TriangleMesh hull = box(glm::dvec3(0.5, 0.3, 0.5));
  physics::FloatingBody body(hull, physics::solid_mass_properties(hull, density), {},
                             physics::WaterProperties{kRhoWater, kG}, {.floor = std::move(floor)});
  body.place(at, orientation);
  for (int i = 0; i < int(seconds * 120); ++i) body.step(1.0 / 120, flat());
  return body;
}

// The lowest of the box's corners above the floor under it (negative: pressed into it).
double clearance(const physics::FloatingBody& body, const physics::FloorHeight& floor) {
  double least = 1e30;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? 0.5 : -0.5, k & 2 ? 0.3 : -0.3, k & 4 ? 0.5 : -0.5);
    const glm::dvec3 p = body.state().position + body.state().orientation * corner;
    least = std::min(least, p.y - floor(p.x, p.z));
  }
  return least;
}

TEST(FloatingBody, ADenseBodyComesToRestOnAFlatFloor) {
  const physics::FloorHeight floor = [](double, double) { return -5.0; };
  for (double density : {2 * kRhoWater, 20000.0}) {
    const physics::FloatingBody body =
        on_floor(density, floor, glm::dvec3(0, 0, 0), 20, glm::angleAxis(0.4, glm::dvec3(1, 0, 0)));
    const double gap = clearance(body, floor);
    RecordProperty("clearance_m_" + std::to_string(int(density)), std::to_string(gap));
    EXPECT_LT(gap, 0.0) << "it should press into the floor a little";
    EXPECT_GT(gap, -0.03) << density << " kg/m^3";
    EXPECT_LT(glm::length(body.state().velocity), 1e-3) << density << " kg/m^3";
    EXPECT_LT(glm::length(body.state().angular_velocity), 1e-2) << density << " kg/m^3";
    EXPECT_GT((body.state().orientation * glm::dvec3(0, 1, 0)).y, 0.999) << "it lies flat";
  }
}

TEST(FloatingBody, ADenseBodyStaysPutOnASlope) {
  // 11° (tan = 0.2), less than friction's 0.6: it lands, and once it rests it does not creep.
  const physics::FloorHeight floor = [](double x, double) { return -5.0 + 0.2 * x; };
  physics::FloatingBody body = on_floor(20000.0, floor, glm::dvec3(0, 0, 0), 10);
  const glm::dvec3 rested = body.state().position;
  for (int i = 0; i < 10 * 120; ++i) body.step(1.0 / 120, flat());
  const double gap = clearance(body, floor);
  RecordProperty("clearance_m", std::to_string(gap));
  RecordProperty("crept_m", std::to_string(glm::distance(body.state().position, rested)));
  EXPECT_GT(gap, -0.03);
  EXPECT_LT(gap, 0.01);
  EXPECT_LT(glm::distance(body.state().position, rested), 0.005);
  EXPECT_LT(glm::length(body.state().velocity), 1e-3);
  // On a slope steeper than friction holds (tan 31° = 0.6 < 1), it slides down (−x).
  const physics::FloorHeight steep = [](double x, double) { return -5.0 + 1.0 * x; };
  const physics::FloatingBody slider = on_floor(20000.0, steep, glm::dvec3(0, 0, 0), 5);
  EXPECT_LT(slider.state().position.x, -1.0);
}

TEST(FloatingBody, ALightBodyReleasedOnTheFloorRisesAndFloats) {
  const physics::FloorHeight floor = [](double, double) { return -5.0; };
  // Half water's density, its bottom on the floor: it rises and floats at half its height.
  const physics::FloatingBody body = on_floor(kRhoWater / 2, floor, glm::dvec3(0, -4.7, 0), 60);
  EXPECT_NEAR(body.state().position.y, 0.0, 0.02 * 0.6);
  EXPECT_EQ(body.last_floor_push().points, 0);
}

// The time between the first `count` downward crossings of the centre through y = 0 (s), stepping at 120 Hz.
double decay_period(physics::FloatingBody& body, int count) {
  std::vector<double> crossings;
  double last = body.state().position.y;
  for (int i = 1; i < 120 * 60 && int(crossings.size()) < count + 1; ++i) {
    body.step(1.0 / 120, flat());
    const double y = body.state().position.y;
    if (last > 0 && y <= 0) crossings.push_back((i - 1 + last / (last - y)) / 120.0);
    last = y;
  }
  return crossings.size() > 1 ? (crossings.back() - crossings.front()) / double(crossings.size() - 1) : 0.0;
}

// The IEA OES Task 10 floating sphere: R = 5 m, half submerged in fresh water (m = ρ·2/3·πR³ = 261.8 t),
// released 1 m above its rest. Its heave decays with the period 2π·sqrt((m + a)/K), K = ρgπR², a the
// hemisphere's added mass near resonance (Hulme 1982: μ = 0.422 at kR = 1.055): 4.37 s. The pressure alone
// gives 2π·sqrt(m/K) = 3.66 s.
TEST(FloatingBody, TheTask10SphereDecaysWithItsAddedMassPeriod) {
  const double rho = 1000.0, radius = 5.0;
  const physics::TriangleMesh hull = physics::uv_sphere(radius, 32);
  const physics::MassProperties mass = physics::solid_mass_properties(hull, rho / 2);
  ASSERT_NEAR(mass.mass, 261.8e3, 0.01 * 261.8e3);
  auto released = [&](bool radiation) {
    physics::FloatingBody body(hull, mass, {0, 0, 0, 0}, {rho, kG}, {.radiation = {.enabled = radiation}});
    body.place(glm::dvec3(0, 1.0, 0), glm::dquat(1, 0, 0, 0));
    return body;
  };
  const double expected = 2 * std::numbers::pi * std::sqrt(2 * radius * 1.422 / (3 * kG));
  physics::FloatingBody with = released(true), without = released(false);
  const double period = decay_period(with, 3), bare = decay_period(without, 3);
  RecordProperty("period_s", std::to_string(period));
  RecordProperty("period_without_radiation_s", std::to_string(bare));
  EXPECT_NEAR(period, expected, 0.1 * expected);
  EXPECT_NEAR(bare, 2 * std::numbers::pi * std::sqrt(2 * radius / (3 * kG)), 0.05 * expected);
  // Radiation damping: the swing decays (ζ = ν/(2(1 + μ)) ≈ 0.07 a period: to about 0.65 per period).
  EXPECT_LT(std::abs(with.state().position.y), 0.5);
}

TEST(MeshFloor, TheHighestTriangleOverAPointAndNothingBeyond) {
  // Two triangles of the plane y = -3 + 0.5x over [0, 4] x [0, 2], and a ledge at y = -1 over x < 1.
  const physics::MeshFloor floor(
      {{0, -3, 0}, {4, -1, 0}, {4, -1, 2}, {0, -3, 2}, {0, -1, 0}, {1, -1, 0}, {0, -1, 2}},
      {0, 1, 2, 0, 2, 3, 4, 5, 6});
  EXPECT_NEAR(floor.height(3.0, 1.0), -1.5, 1e-12);
  EXPECT_NEAR(floor.height(0.2, 0.2), -1.0, 1e-12);  // under the ledge: the ledge
  EXPECT_EQ(floor.height(5.0, 1.0), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace lagoon::test
