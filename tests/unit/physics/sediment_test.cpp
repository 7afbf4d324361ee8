// Sediment clouds (compute/physics/sediment.h, issue 14) against the physics they claim, checked on the
// concentration field alone: a cloud solves the advection-diffusion equation with the set settling velocity,
// diffusivity and current; the suspended mass's centre sinks at the settling velocity; what sinks below the
// floor leaves the water and nothing is lost; a hull above the release height stirs up nothing; and the
// closed-form optical depth the shaders use (shaders/shared/sediment_math.h) equals the concentration
// integrated along the ray, and a ray segment that misses the clouds' reach box gets nothing from any of
// them.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "physics/sediment.h"

namespace lagoon::test {
namespace {

using physics::SedimentCloud;
using physics::SedimentParams;
using physics::SedimentPuff;

constexpr double kFloorDepth = 10;
const physics::FloorDepth kFlat = [](glm::dvec2) { return kFloorDepth; };

// A stirrer whose lowest point is `altitude` above the flat floor at (x, z), for t <= until_s, and far
// above it afterwards.
physics::StirrerBottom held_at(double x, double z, double altitude, double until_s = 1e9) {
  return [=](double t) { return glm::dvec3(x, -kFloorDepth + (t <= until_s ? altitude : 50.0), z); };
}

double concentration(const std::vector<SedimentPuff>& puffs, glm::dvec3 p) {
  return physics::sediment_concentration(puffs, kFlat, p);
}

TEST(Sediment, ACloudSolvesTheAdvectionDiffusionEquation) {
  // ∂C/∂t = K ∇²C + w_s ∂C/∂y - u · ∇C: sinking at w_s, spreading at K, drifting with u. A cloud that
  // spread as σ² = r² + K t (half the rate) or sank at 2 w_s leaves a residual of the order of the terms.
  const SedimentParams p{.rise_m = 6,
                         .radius_m = 0.5,
                         .settling_mps = 0.02,
                         .diffusivity_m2_s = 0.01,
                         .current_mps = {0.3, -0.1}};
  const SedimentCloud cloud(p, kFlat, {});
  const glm::dvec2 origin(2, 3);
  const double age = 20, dt = 1e-3, h = 2e-3;
  auto c = [&](glm::dvec3 x, double t) { return concentration({cloud.puff(origin, 100, t)}, x); };
  const SedimentPuff now = cloud.puff(origin, 100, age);
  const glm::dvec3 offsets[] = {{0.3, 0.2, -0.4}, {-0.5, -0.6, 0.1}, {0.9, 0.4, 0.7}, {-0.2, 0.8, -1.0}};
  for (const glm::dvec3& o : offsets) {
    const glm::dvec3 x = now.centre + o * now.sigma;
    const double dcdt = (c(x, age + dt) - c(x, age - dt)) / (2 * dt);
    glm::dvec3 grad(0.0), second(0.0);
    for (int a = 0; a < 3; ++a) {
      glm::dvec3 e(0.0);
      e[a] = h;
      const double plus = c(x + e, age), minus = c(x - e, age), mid = c(x, age);
      grad[a] = (plus - minus) / (2 * h);
      second[a] = (plus - 2 * mid + minus) / (h * h);
    }
    const double diffusion = p.diffusivity_m2_s * (second.x + second.y + second.z);
    const double settling = p.settling_mps * grad.y;
    const double drift = -(p.current_mps.x * grad.x + p.current_mps.y * grad.z);
    const double scale = std::abs(diffusion) + std::abs(settling) + std::abs(drift);
    EXPECT_NEAR(dcdt, diffusion + settling + drift, 1e-3 * scale) << "at offset " << o.x << " " << o.y;
  }
}

// ∫ C and ∫ y C over a box around the clouds (midpoint rule, 0.1 m cells).
struct Moments {
  double mass = 0, mean_y = 0;
};
Moments moments(const std::vector<SedimentPuff>& puffs, glm::dvec3 lo, glm::dvec3 hi) {
  const double cell = 0.1;
  Moments m;
  double first = 0;
  for (double y = lo.y + cell / 2; y < hi.y; y += cell)
    for (double x = lo.x + cell / 2; x < hi.x; x += cell)
      for (double z = lo.z + cell / 2; z < hi.z; z += cell) {
        const double c = concentration(puffs, {x, y, z}) * cell * cell * cell;
        m.mass += c;
        first += c * y;
      }
  m.mean_y = first / m.mass;
  return m;
}

// Seed 002 §3.4: the sediment is thrown out radially from a point and rises. A new cloud leaves the floor a
// fifth of radius_m across and reaches rise_m and radius_m as 1 - e^(-age / burst_s).
TEST(Sediment, ANewCloudBurstsUpAndOutFromTheFloor) {
  const SedimentParams p{
      .rise_m = 2, .radius_m = 0.5, .settling_mps = 0, .diffusivity_m2_s = 0, .burst_s = 0.4};
  const SedimentCloud cloud(p, kFlat, {});
  const SedimentPuff born = cloud.puff({1, 2}, 10, 0);
  EXPECT_NEAR(born.centre.y, -kFloorDepth, 1e-12) << "released on the floor";
  EXPECT_NEAR(born.sigma, 0.1, 1e-12);
  for (const double age : {0.2, 0.4, 1.0}) {
    const SedimentPuff now = cloud.puff({1, 2}, 10, age);
    const double burst = 1 - std::exp(-age / 0.4);
    EXPECT_NEAR(now.centre.y, -kFloorDepth + 2 * burst, 1e-12) << "age " << age;
    EXPECT_NEAR(now.sigma, 0.5 * (0.2 + 0.8 * burst), 1e-12) << "age " << age;
  }
  const SedimentPuff grown = cloud.puff({1, 2}, 10, 4.0);  // ten burst times
  EXPECT_NEAR(grown.centre.y, -kFloorDepth + 2, 1e-3);
  EXPECT_NEAR(grown.sigma, 0.5, 1e-3);
  // burst_s = 0: born at its full height and size, as before the burst.
  const SedimentCloud at_once({.rise_m = 2, .radius_m = 0.5, .burst_s = 0}, kFlat, {});
  EXPECT_NEAR(at_once.puff({1, 2}, 10, 0).centre.y, -kFloorDepth + 2, 1e-12);
}

TEST(Sediment, TheSuspendedMassSinksAtTheSettlingVelocity) {
  // A hull just above the floor for five seconds releases five clouds 5 m up; 30 s apart, their mass centre
  // has sunk by 30 w_s, and all of it is still in the water.
  const SedimentParams p{.release_height_m = 1.5,
                         .release_g_per_s = 20,
                         .rise_m = 5,
                         .radius_m = 0.4,
                         .settling_mps = 0.03,
                         .diffusivity_m2_s = 0.002};
  const SedimentCloud cloud(p, kFlat, {held_at(0, 0, 0.3, 5.5)});
  const double released = cloud.released_g(60);
  ASSERT_NEAR(released, 5 * 20 * (1 - 0.3 / 1.5), 1e-9);
  const glm::dvec3 lo(-3, -kFloorDepth, -3), hi(3, -2, 3);
  const Moments early = moments(cloud.puffs(30), lo, hi), late = moments(cloud.puffs(60), lo, hi);
  EXPECT_NEAR(early.mass, released, 0.01 * released);
  EXPECT_NEAR(late.mass, released, 0.01 * released);
  EXPECT_NEAR((late.mean_y - early.mean_y) / 30.0, -p.settling_mps, 0.02 * p.settling_mps);
}

TEST(Sediment, WhatSinksBelowTheFloorHasSettledAndNoneIsLost) {
  const SedimentParams p{
      .release_g_per_s = 10, .rise_m = 1, .radius_m = 0.5, .settling_mps = 0.02, .diffusivity_m2_s = 0.005};
  const SedimentCloud cloud(p, kFlat, {held_at(0, 0, 0.0, 1.5)});
  const double released = cloud.released_g(1000);
  ASSERT_GT(released, 0);
  // Straddling the floor: the suspended mass is what the concentration holds above it.
  for (double t : {30.0, 60.0, 90.0}) {
    const Moments in_water = moments(cloud.puffs(t), {-4, -kFloorDepth, -4}, {4, -kFloorDepth + 6, 4});
    EXPECT_NEAR(cloud.suspended_g(t), in_water.mass, 0.01 * released) << "at " << t << " s";
    EXPECT_LT(cloud.suspended_g(t), released);
  }
  EXPECT_LT(cloud.suspended_g(60), cloud.suspended_g(30));
  // Sunk 5 sigma below the floor: the water has cleared.
  EXPECT_LT(cloud.suspended_g(400), 1e-3 * released);
  EXPECT_NEAR(cloud.released_g(400), released, 1e-12);
}

TEST(Sediment, AHullAboveTheReleaseHeightReleasesNone) {
  const SedimentParams p{.release_height_m = 1.5, .release_g_per_s = 40};
  const SedimentCloud above(p, kFlat, {held_at(0, 0, 1.6)});
  EXPECT_EQ(above.released_g(120), 0.0);
  EXPECT_TRUE(above.puffs(120).empty());
  const SedimentCloud below(p, kFlat, {held_at(0, 0, 1.4)});
  EXPECT_GT(below.released_g(120), 0.0);
  EXPECT_FALSE(below.puffs(120).empty());
  // The strength falls linearly with the height above the floor.
  EXPECT_DOUBLE_EQ(below.release_rate(0.0), 40.0);
  EXPECT_DOUBLE_EQ(below.release_rate(0.75), 20.0);
  EXPECT_DOUBLE_EQ(below.release_rate(1.5), 0.0);
  // Dry land (no depth) stirs nothing either.
  const SedimentCloud dry(p, [](glm::dvec2) { return -1.0; }, {held_at(0, 0, 0.0)});
  EXPECT_EQ(dry.released_g(60), 0.0);
}

TEST(Sediment, TheRayClosedFormIsTheConcentrationAlongTheRay) {
  const SedimentParams p{.rise_m = 4, .radius_m = 0.6, .diffusivity_m2_s = 0.01};
  const SedimentCloud cloud(p, kFlat, {});
  const std::vector<SedimentPuff> puffs = {cloud.puff({0, 0}, 30, 5), cloud.puff({1.5, -0.5}, 12, 40),
                                           cloud.puff({-2, 1}, 50, 100)};
  const double attenuation = 0.4;
  struct Ray {
    glm::dvec3 origin, dir;
    double length;
  };
  const Ray rays[] = {{{-8, -5.5, 0.2}, glm::normalize(glm::dvec3(1, 0.05, 0)), 16},    // through all
                      {{-8, -5.5, 0.2}, glm::normalize(glm::dvec3(1, 0.05, 0)), 8.3},   // ends inside
                      {{0.5, 0, 0.5}, glm::normalize(glm::dvec3(0.1, -1, 0.05)), 9.5},  // from above
                      {{-1, -6.2, -3}, glm::normalize(glm::dvec3(0.2, 0.1, 1)), 6}};
  for (const Ray& r : rays) {
    const glm::dvec2 closed = physics::sediment_ray(puffs, attenuation, r.origin, r.dir, r.length);
    const int n = 20000;
    const double dt = r.length / n;
    double tau = 0, moment = 0;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * dt;
      const double k = attenuation * concentration(puffs, r.origin + r.dir * t) * dt;
      tau += k;
      moment += k * t;
    }
    ASSERT_GT(tau, 1e-3);
    EXPECT_NEAR(closed.x, tau, 1e-5 * tau + 1e-7);
    EXPECT_NEAR(closed.y / closed.x, moment / tau, 1e-4 * r.length);
  }
}

// The shaders test a pixel's ray segment against the box of the clouds' reach before their loop over the
// clouds (issue 34: sediment costs every water pixel): a segment that misses the box must get exactly what
// the loop would add, nothing, or the box would change the picture. Random segments around five clouds: many
// miss the box, many meet it, and none that misses has a non-zero optical depth. A segment that ends short
// of a cloud it points at is cut as the loop cuts it: what it leaves out is below e^-10/2 of the cloud's
// depth through its centre.
TEST(Sediment, ASegmentThatMissesTheCloudsReachBoxGetsNothingFromAnyOfThem) {
  const SedimentParams p{.rise_m = 2, .radius_m = 0.5, .diffusivity_m2_s = 0.02};
  const SedimentCloud cloud(p, kFlat, {});
  const std::vector<SedimentPuff> puffs = {cloud.puff({0, 0}, 30, 5), cloud.puff({3, 1}, 12, 20),
                                           cloud.puff({5, 4}, 50, 60), cloud.puff({7, 6}, 5, 2),
                                           cloud.puff({8, 9}, 20, 30)};
  const physics::SedimentBox box = physics::sediment_reach(puffs);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> across(-15, 25), depth(-10, 0), unit(-1, 1), length(0.5, 30);
  int missed = 0, met = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 origin(across(rng), depth(rng), across(rng));
    glm::dvec3 dir(unit(rng), unit(rng), unit(rng));
    if (glm::length(dir) < 1e-3) continue;
    dir = glm::normalize(dir);
    if (i % 10 == 0) dir.x = 0, dir = glm::normalize(dir);  // parallel to a pair of the box's faces
    const double len = length(rng);
    const glm::dvec2 ray = physics::sediment_ray(puffs, 0.4, origin, dir, len);
    if (physics::segment_meets(box, origin, dir, len)) {
      ++met;
      continue;
    }
    ++missed;
    ASSERT_EQ(ray.x, 0.0) << "a segment from (" << origin.x << ", " << origin.y << ", " << origin.z
                          << ") missing the box still crosses a cloud";
    ASSERT_EQ(ray.y, 0.0);
  }
  EXPECT_GT(missed, 4000);
  EXPECT_GT(met, 4000);

  // Aimed at the first cloud's centre from 6 σ away and ending 4.6 σ short of it.
  const SedimentPuff& q = puffs[0];
  const glm::dvec3 dir(1, 0, 0), origin = q.centre - 6.0 * q.sigma * dir;
  const double len = 1.4 * q.sigma;
  EXPECT_EQ(physics::sediment_ray(puffs, 0.4, origin, dir, len).x, 0.0);
  const int n = 20000;
  double left_out = 0;
  for (int i = 0; i < n; ++i)
    left_out += 0.4 * concentration({q}, origin + dir * ((i + 0.5) * len / n)) * len / n;
  const double through_centre = physics::sediment_ray({&q, 1}, 0.4, origin, dir, 12.0 * q.sigma).x;
  EXPECT_GT(left_out, 0.0);
  EXPECT_LT(left_out, 0.5 * std::exp(-10.0) * through_centre);
}

}  // namespace
}  // namespace lagoon::test
