// LocalHeights (compute/ocean/local_heights.h): the sea's height around a body from WaveQuery knots,
// interpolated in time and space, against WaveQuery itself at the exact time; and a floating box riding the
// default scene's sea with it.
#include "ocean/local_heights.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "physics/floating_body.h"
#include "support/shipped_scene.h"

namespace lagoon::test {
namespace {

TEST(LocalHeights, FollowWaveQueryBetweenKnots) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  ocean::LocalHeights local(s.ocean, spectra, {});
  ocean::WaveQuery exact(s.ocean, spectra);
  const glm::dvec2 centre(3.0, -7.0);
  double sum2 = 0, error2 = 0, worst = 0;
  int count = 0;
  // What buoyancy sees: the mean height over a hull's patch. Waves shorter than the lattice resolves (under
  // 4 spacings, 2 m) are not there, but over a 1 m square they average out in the truth as well.
  auto patch_mean = [](auto&& height, double x0, double z0) {
    double sum = 0;
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b) sum += height(x0 + 0.2 * a, z0 + 0.2 * b);
    return sum / 25;
  };
  for (int step = 0; step < 12; ++step) {
    const double t = 4.0 + 0.137 * step;  // between knots, at every phase of the interval
    local.update(t, centre);
    for (int i = -2; i <= 1; ++i)
      for (int j = -2; j <= 1; ++j) {
        const double x = centre.x + 1.03 * i, z = centre.y + 0.97 * j;
        const double h =
            patch_mean([&](double px, double pz) { return exact.sample(t, px, pz).height; }, x, z);
        const double e = patch_mean([&](double px, double pz) { return local.height(px, pz); }, x, z) - h;
        sum2 += h * h;
        error2 += e * e;
        worst = std::max(worst, std::abs(e));
        ++count;
      }
  }
  const double rms = std::sqrt(sum2 / count), rms_error = std::sqrt(error2 / count);
  std::printf(
      "LocalHeights vs WaveQuery, 1 m patch means: rms error %.4f m (worst %.4f m), rms %.3f m, %d knots\n",
      rms_error, worst, rms, local.knots_sampled());
  RecordProperty("rms_error_m", std::to_string(rms_error));
  RecordProperty("sea_rms_m", std::to_string(rms));
  EXPECT_GT(rms, 0.03) << "too calm a sea to tell";
  EXPECT_LT(rms_error, 0.1 * rms);
  EXPECT_LE(local.knots_sampled(), 12) << "knots are sampled again and again";
}

// A knot sampled ahead on the query's worker answers exactly as one sampled when it is needed: a lattice
// stepped at 120 Hz, waiting each step until the prefetched time is ready (as a paced 60 Hz loop has time
// for), against one on its own query updated at the last time only.
TEST(LocalHeights, AKnotSampledAheadIsTheKnotSampledWhenNeeded) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  auto query = std::make_shared<ocean::WaveQuery>(s.ocean, spectra);
  ocean::LocalHeights stepped(query, {}), whole(s.ocean, spectra, {});
  const glm::dvec2 centre(3.0, -7.0);
  const double interval = ocean::LocalHeightsOptions{}.knot_interval_s;
  double t = 2.0;
  for (int step = 0; step < 60; ++step, t += 1.0 / 120.0) {
    stepped.update(t, centre);
    const double ahead = (std::floor(t / interval) + 3) * interval;
    for (int wait = 0; wait < 5000 && !query->ready(ahead); ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  whole.update(t - 1.0 / 120.0, centre);
  const double spacing = ocean::LocalHeightsOptions{}.spacing_m;
  int points = 0;
  for (double x = centre.x - 3; x <= centre.x + 3; x += 0.37 * spacing)
    for (double z = centre.y - 3; z <= centre.y + 3; z += 0.41 * spacing, ++points)
      ASSERT_EQ(stepped.height(x, z), whole.height(x, z)) << x << ", " << z;
  EXPECT_GT(points, 900);
}

// A lattice that moves with its body keeps the heights of the points it still covers and samples the rest:
// a body under way (diagonally, so both axes shift) must answer at every step as a lattice placed fresh
// where it is at that time, on its own query: the same points of the world-fixed grid, the same heights there
// (to the rounding of the two lattices' own coordinates; a point taken from the wrong old point is off by
// the waves' height).
TEST(LocalHeights, ALatticeThatMovesAnswersAsOnePlacedThereFresh) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  ocean::LocalHeights moving(s.ocean, spectra, {});
  const glm::dvec2 start(3.0, -7.0), velocity(4.0, 2.5);  // m/s: a boat under way
  int moves = 0;
  glm::dvec2 last_corner(0.0);
  for (int step = 0; step < 360; ++step) {
    const double t = 2.0 + step / 120.0;
    const glm::dvec2 at = start + velocity * (t - 2.0);
    moving.update(t, at);
    if (step % 30 != 29) continue;
    ocean::LocalHeights fresh(s.ocean, spectra, {});
    fresh.update(t, at);
    // Within 1 m of the body: its taps stay inside both lattices (the body is kept 1.9 m from the edge).
    for (double dx = -1.0; dx <= 1.0; dx += 0.13)
      for (double dz = -1.0; dz <= 1.0; dz += 0.17)
        ASSERT_NEAR(moving.height(at.x + dx, at.y + dz), fresh.height(at.x + dx, at.y + dz), 1e-12)
            << "t = " << t << " at " << dx << ", " << dz;
    const glm::dvec2 corner(std::floor(at.x / 4.0), std::floor(at.y / 4.0));
    moves += corner != last_corner ? 1 : 0;
    last_corner = corner;
  }
  EXPECT_GE(moves, 4) << "the body must travel several lattice quarters (12 m in 3 s)";
}

// A lattice told to keep its centre keep_inside_m from its edge (the bodies' lattices, sized to a hull)
// recentres by that rule: for a body drifting across it, every point within keep_inside_m minus the bicubic
// taps' reach of the body answers as a lattice four times larger placed fresh there, never clamped at an
// edge.
TEST(LocalHeights, ALatticeKeepsItsCentreTheDistanceAskedFromItsEdge) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  const ocean::LocalHeightsOptions small{.points_per_side = 25, .keep_inside_m = 2.0};
  ocean::LocalHeights moving(s.ocean, spectra, small);
  const glm::dvec2 start(3.0, -7.0), velocity(-1.5, 2.5);
  for (int step = 0; step < 240; ++step) {
    const double t = 2.0 + step / 120.0;
    const glm::dvec2 at = start + velocity * (t - 2.0);
    moving.update(t, at);
    if (step % 20 != 19) continue;
    ocean::LocalHeights large(s.ocean, spectra, {.points_per_side = 41});
    large.update(t, at);
    for (double dx = -1.0; dx <= 1.0; dx += 0.13)  // 2 m asked, less the taps' 1 m (two spacings)
      for (double dz = -1.0; dz <= 1.0; dz += 0.17)
        ASSERT_NEAR(moving.height(at.x + dx, at.y + dz), large.height(at.x + dx, at.y + dz), 1e-12)
            << "t = " << t << " at " << dx << ", " << dz;
  }
}

// add(): heights from another source (the wakes) added where height() reads for a box are interpolated with
// the sea's: a plane added must come back as itself inside the box (Catmull-Rom reproduces planes), up to its
// edges, and leave the lattice untouched far from it. highest(lo, hi) bounds the sum in the box, and a bump
// added inside shows in it.
TEST(LocalHeights, HeightsAddedInABoxAreInterpolatedWithTheSeaAndBoundedThere) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  ocean::LocalHeights sea(s.ocean, spectra, {}), summed(s.ocean, spectra, {});
  const glm::dvec2 centre(1.0, 2.0), lo(-1.2, 0.3), hi(2.9, 3.1);
  sea.update(3.3, centre);
  summed.update(3.3, centre);
  const auto plane = [](glm::dvec2 p) { return 0.3 + 0.05 * p.x - 0.02 * p.y; };
  summed.add(lo, hi, [&](std::span<const glm::dvec2> points, std::span<double> out) {
    for (size_t i = 0; i < points.size(); ++i) out[i] += plane(points[i]);
  });
  for (double x = lo.x; x <= hi.x + 1e-9; x += 0.1)
    for (double z = lo.y; z <= hi.y + 1e-9; z += 0.1)
      ASSERT_NEAR(summed.height(x, z) - sea.height(x, z), plane({x, z}), 1e-9) << x << ", " << z;
  // The lattice's last rows (z from 5 m; it spans -2 .. 5.5 m) are beyond the taps of any point in the box.
  for (double x = -2.0; x <= 4.0; x += 0.3) ASSERT_EQ(summed.height(x, 5.2), sea.height(x, 5.2)) << x;
  double top = -1e9;
  for (double x = lo.x; x <= hi.x; x += 0.05)
    for (double z = lo.y; z <= hi.y; z += 0.05) top = std::max(top, summed.height(x, z));
  EXPECT_LE(top, summed.highest(lo, hi));
  EXPECT_LE(top, summed.highest());
  EXPECT_GT(top, summed.highest(lo, hi) - 0.3) << "a bound far above the water spares nothing";
  summed.add({0.5, 1.5}, {0.5, 1.5}, [](std::span<const glm::dvec2> points, std::span<double> out) {
    for (size_t i = 0; i < points.size(); ++i)
      out[i] += glm::length(points[i] - glm::dvec2(0.5, 1.5)) < 0.1 ? 2.0 : 0.0;  // a lattice point
  });
  EXPECT_GE(summed.highest(lo, hi), summed.height(0.5, 1.5));
  EXPECT_GT(summed.height(0.5, 1.5), top + 1.0) << "the bump is there";
}

// highest() bounds every height() at the last update's time (the bodies skip their dry triangles by it),
// and not by much: within the lattice's range of its highest point.
TEST(LocalHeights, NoHeightIsAboveTheHighest) {
  const scene::Scene s = shipped_scene("default");
  ocean::LocalHeights local(s.ocean, ocean::make_cascade_spectra(s.ocean), {});
  for (int step = 0; step < 5; ++step) {
    const double t = 3.0 + 0.37 * step;
    local.update(t, {1.0, 2.0});
    double top = -1e9;
    for (double x = -4.0; x <= 6.0; x += 0.05)
      for (double z = -3.0; z <= 7.0; z += 0.05) top = std::max(top, local.height(x, z));
    EXPECT_LE(top, local.highest()) << "t = " << t;
    EXPECT_GT(top, local.highest() - 0.5) << "a bound far above the water spares nothing";
    // A hull's points asked in one batch answer as each asked alone, inside the lattice and past its edge.
    std::vector<glm::dvec2> points;
    for (double x = -9.0; x <= 11.0; x += 0.37)
      for (double z = -8.0; z <= 12.0; z += 0.41) points.push_back({x, z});
    std::vector<double> batch(points.size());
    local.heights(points, batch);
    for (size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(batch[i], local.height(points[i].x, points[i].y)) << points[i].x << ", " << points[i].y;
  }
}

TEST(LocalHeights, ABoxRidesTheScenesSea) {
  const scene::Scene s = shipped_scene("default");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  physics::TriangleMesh hull;
  for (int k = 0; k < 8; ++k)
    hull.vertices.push_back({k & 1 ? 0.5 : -0.5, k & 2 ? 0.2 : -0.2, k & 4 ? 0.5 : -0.5});
  const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) hull.indices.insert(hull.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  auto run = [&](std::vector<double>* water_at_body) {
    ocean::LocalHeights local(s.ocean, spectra, {});
    physics::FloatingBody body(hull, physics::solid_mass_properties(hull, 1025.0 / 2), {}, {});
    body.place({0, 0, 0}, glm::dquat(1, 0, 0, 0));
    std::vector<double> heave;
    const double dt = 1.0 / 120;
    for (int i = 0; i < 20 * 120; ++i) {
      const double t = i * dt;
      local.update(t, glm::dvec2(body.state().position.x, body.state().position.z));
      body.step(dt, [&](double x, double z) { return local.height(x, z); });
      if (i >= 5 * 120) {
        heave.push_back(body.state().position.y);
        if (water_at_body)
          water_at_body->push_back(local.height(body.state().position.x, body.state().position.z));
      }
    }
    return heave;
  };
  std::vector<double> water;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> heave = run(&water);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // It rides the sea: its centre follows the water at its centre (a half-density box floats with its centre
  // at the surface), closely for waves much longer than the box.
  double mean_h = 0, mean_w = 0;
  for (size_t i = 0; i < heave.size(); ++i)
    mean_h += heave[i] / heave.size(), mean_w += water[i] / water.size();
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < heave.size(); ++i) {
    sxy += (heave[i] - mean_h) * (water[i] - mean_w);
    sxx += (heave[i] - mean_h) * (heave[i] - mean_h);
    syy += (water[i] - mean_w) * (water[i] - mean_w);
  }
  const double correlation = sxy / std::sqrt(sxx * syy), ratio = std::sqrt(sxx / syy);
  std::printf("box in the default sea: heave/water rms %.3f, correlation %.3f, 20 s simulated in %.0f ms\n",
              ratio, correlation, ms);
  RecordProperty("heave_ratio", std::to_string(ratio));
  RecordProperty("correlation", std::to_string(correlation));
  EXPECT_GT(correlation, 0.9);
  EXPECT_NEAR(ratio, 1.0, 0.3);
  // Deterministic: the same run gives the same bits.
  EXPECT_EQ(run(nullptr), heave);
}

}  // namespace
}  // namespace lagoon::test
