// The wakes under the hulls (world/wake_heights.h): the bodies' coarse CPU layer holds the picture's layer
// without its shortest waves, the layers add up per vehicle, a box rides a wake, and a floating object feels
// a passing boat only once its wake has come.
#include "world/wake_heights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <future>
#include <memory>
#include <vector>

#include "fft/cpu_fft.h"
#include "physics/floating_body.h"
#include "support/box_mesh.h"
#include "support/shipped_scene.h"
#include "world/floating_objects.h"

namespace lagoon::test {
namespace {

// A boat on a straight line through the window's centre, and (optionally) a second one crossing it.
const std::string kBoat =
    R"({"name":"boat","file":"assets/boat.gltf","path":{"waypoints":[[-30,-6],[60,-6]],"speed_mps":5}})";
const std::string kCrossing =
    R"({"name":"crossing","file":"assets/boat.gltf","path":{"waypoints":[[10,-40],[10,60]],"speed_mps":4}})";

world::VehicleWakes wakes_of(const scene::Scene& s) {
  auto w = world::VehicleWakes::create(s);
  EXPECT_TRUE(w) << w.error().message;
  return w ? *w : world::VehicleWakes{};
}

TEST(WakeHeights, TheBodiesLayerIsThePicturesLayerWithoutItsShortestWaves) {
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "]"});
  const world::VehicleWakes wakes = wakes_of(s);
  ASSERT_FALSE(wakes.empty());
  // The picture's layer: 512 cells of 0.25 m, the window centred on the origin as the bodies' is.
  const ocean::DynamicLayerParams fine = wakes.params();
  ASSERT_EQ(fine.n, 512u);
  ocean::DynamicLayerCpu picture(fine);
  picture.set_window({-256, -256});
  const int steps = 80;
  for (int k = 0; k < steps; ++k) {
    const auto sources = wakes.sources(k * wakes.step_s());
    picture.step(wakes.step_s(), sources);
  }
  world::WakeHeights bodies(wakes, 128);
  bodies.advance(steps * wakes.step_s(), glm::dvec2(0.0));
  ASSERT_DOUBLE_EQ(bodies.params().cell_m, 1.0);

  // The picture's heights with the modes the coarse grid cannot hold taken out (|index| >= 64 along either
  // axis), then sampled at the coarse cells.
  std::vector<std::complex<double>> h(picture.state().size());
  for (size_t c = 0; c < h.size(); ++c) h[c] = picture.state()[c].real();
  fft::CpuFft2d(512, false).transform(h, 1, 2);
  for (int j = 0; j < 512; ++j)
    for (int i = 0; i < 512; ++i) {
      const int fi = i < 256 ? i : i - 512, fj = j < 256 ? j : j - 512;
      if (std::abs(fi) >= 64 || std::abs(fj) >= 64) h[size_t(j) * 512 + i] = 0;
    }
  fft::CpuFft2d(512, true).transform(h, 1, 2);
  double diff = 0, norm = 0, raw = 0;
  for (int b = -48; b < 48; ++b)  // inside the 16 m border
    for (int a = -48; a < 48; ++a) {
      const double reference =
          h[size_t((b * 4 + 512) % 512) * 512 + size_t((a * 4 + 512) % 512)].real() / (512.0 * 512.0);
      const double coarse = bodies.height(glm::dvec2(a, b));
      diff += (coarse - reference) * (coarse - reference);
      norm += reference * reference;
      raw += (coarse - picture.height(4 * a, 4 * b)) * (coarse - picture.height(4 * a, 4 * b));
    }
  ASSERT_GT(std::sqrt(norm / (96 * 96)), 0.01) << "the boat made no wake to compare";
  const double relative = std::sqrt(diff / norm);
  RecordProperty("relative_l2_to_low_passed_picture", std::to_string(relative));
  RecordProperty("relative_l2_to_picture", std::to_string(std::sqrt(raw / norm)));
  EXPECT_LT(relative, 0.05);
}

TEST(WakeHeights, AVehicleFeelsEveryWakeButItsOwn) {
  const scene::Scene both = shipped_scene("default", {"vehicles=[" + kBoat + "," + kCrossing + "]"});
  const scene::Scene first = shipped_scene("default", {"vehicles=[" + kBoat + "]"});
  const scene::Scene second = shipped_scene("default", {"vehicles=[" + kCrossing + "]"});
  world::WakeHeights all(wakes_of(both), 64), one(wakes_of(first), 64), two(wakes_of(second), 64);
  const double t = 7.35;  // between two steps
  for (world::WakeHeights* w : {&all, &one, &two}) w->advance(t, glm::dvec2(5, 5));
  double largest = 0;
  for (double x = -40; x <= 40; x += 3.7)
    for (double z = -40; z <= 40; z += 4.1) {
      const glm::dvec2 p(x, z);
      largest = std::max(largest, std::abs(two.height(p)));
      EXPECT_NEAR(all.height(p), one.height(p) + two.height(p), 1e-12);
      EXPECT_NEAR(all.height(p, 0), two.height(p), 1e-12) << "the boat feels the crossing boat's wake only";
      EXPECT_NEAR(all.height(p, 1), one.height(p), 1e-12);
      EXPECT_NEAR(all.rate(p), one.rate(p) + two.rate(p), 1e-12);
    }
  EXPECT_GT(largest, 0.02);
  EXPECT_EQ(all.height(glm::dvec2(500, 500)), 0.0) << "no wake outside the window";
}

TEST(WakeHeights, BetweenStepsTheHeightFollowsItsRate) {
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "]"});
  world::WakeHeights w(wakes_of(s), 64);
  // Across a step boundary (t = 6.0) the interpolated height is smooth and its rate is its derivative.
  const glm::dvec2 p(4, -14);
  const double e = 1e-4;
  for (double t : {5.93, 5.999, 6.0, 6.001, 6.04}) {
    w.advance(t - e, glm::dvec2(0.0));
    const double before = w.height(p);
    w.advance(t + e, glm::dvec2(0.0));
    const double after = w.height(p);
    w.advance(t, glm::dvec2(0.0));
    EXPECT_NEAR((after - before) / (2 * e), w.rate(p), 1e-3 * std::abs(w.rate(p)) + 1e-6) << t;
    EXPECT_NEAR(after, before, 0.05 * std::abs(w.rate(p)) * 2 * e + 1e-6) << "a jump at " << t;
  }
}

TEST(WakeHeights, ACellLookedUpBeforeAnAdvanceAnswersAsAFreshLayerAfterIt) {
  // Cells are summed when first looked up after an advance: one asked for at many earlier times (within a
  // step and across steps) must answer as a fresh layer advanced straight to the last time, everywhere.
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "," + kCrossing + "]"});
  world::WakeHeights used(wakes_of(s), 64), fresh(wakes_of(s), 64);
  std::vector<glm::dvec2> at;
  for (double x = -40; x <= 40; x += 2.7)
    for (double z = -40; z <= 40; z += 3.1) at.push_back({x, z});
  for (double t = 4.0; t < 6.02; t += 1.0 / 120.0) {
    used.advance(t, glm::dvec2(5, 5));
    for (size_t i = 0; i < at.size(); i += 7)
      used.height(at[i], i % 3 == 0 ? 0 : world::WakeHeights::kNoVehicle);
  }
  const double t = 6.02;
  used.advance(t, glm::dvec2(5, 5));
  fresh.advance(t, glm::dvec2(5, 5));
  double largest = 0;
  for (size_t skip : {world::WakeHeights::kNoVehicle, size_t{0}, size_t{1}})
    for (const glm::dvec2& p : at) {
      // The same arithmetic on the same states: equal to the bit.
      ASSERT_EQ(used.height(p, skip), fresh.height(p, skip)) << p.x << ", " << p.y << " skipping " << skip;
      largest = std::max(largest, std::abs(used.height(p, skip)));
    }
  for (const glm::dvec2& p : at) EXPECT_EQ(used.rate(p), fresh.rate(p)) << p.x << ", " << p.y;
  EXPECT_GT(largest, 1e-3) << "the boats' wakes are in the window";
}

// The layers' next step runs on the worker; when the caller needs it before the worker has begun it (a
// catch-up, or a worker busy with the sea's knots), the caller steps it itself, without waiting. Either way
// the same states to the bit.
TEST(WakeHeights, AStepTheWorkerHasNotBegunIsSteppedByTheCallerToTheSameBits) {
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "," + kCrossing + "]"});
  auto worker = std::make_shared<BackgroundWorker>();
  std::promise<void> release, started;
  std::shared_future<void> released = release.get_future().share();
  worker->post([&started, released] {
    started.set_value();
    released.wait_for(std::chrono::seconds(10));  // a broken caller fails the test rather than hanging it
  });
  started.get_future().wait();
  world::WakeHeights held(wakes_of(s), 64, worker), free(wakes_of(s), 64);
  const auto blocked_until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  for (double t = 4.0; t < 6.02; t += 1.0 / 60.0) {
    held.advance(t, glm::dvec2(5, 5));
    free.advance(t, glm::dvec2(5, 5));
  }
  EXPECT_LT(std::chrono::steady_clock::now(), blocked_until) << "the caller waited for the held worker";
  EXPECT_EQ(released.wait_for(std::chrono::seconds(0)), std::future_status::timeout);
  double largest = 0;
  for (double x = -40; x <= 40; x += 2.7)
    for (double z = -40; z <= 40; z += 3.1) {
      ASSERT_EQ(held.height({x, z}), free.height({x, z})) << x << ", " << z;
      ASSERT_EQ(held.rate({x, z}), free.rate({x, z})) << x << ", " << z;
      largest = std::max(largest, std::abs(free.height({x, z})));
    }
  EXPECT_GT(largest, 1e-3) << "the boats' wakes are in the window";
  release.set_value();
}

// The hulls' lattices ask for their points in one batch (add_heights): the batch must answer as height()
// does, to the bit, inside the window, at its edges and outside.
TEST(WakeHeights, ABatchAnswersAsEachPoint) {
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "," + kCrossing + "]"});
  world::WakeHeights w(wakes_of(s), 64);
  w.advance(7.35, glm::dvec2(5, 5));
  std::vector<glm::dvec2> points;
  for (double x = -75; x <= 75; x += 1.37)
    for (double z = -75; z <= 75; z += 1.91) points.push_back({x, z});  // the 128 m window and beyond
  for (size_t skip : {world::WakeHeights::kNoVehicle, size_t{0}, size_t{1}}) {
    std::vector<double> batch(points.size(), 0.25);
    w.add_heights(points, batch, skip);
    for (size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(batch[i], 0.25 + w.height(points[i], skip)) << points[i].x << ", " << points[i].y;
  }
}

TEST(WakeHeights, ASmallBoxRidesAPassingWake) {
  // Calm water but for the boat's wake: a flat 0.5 m box of half water's density 10 m off the boat's line
  // heaves with the wake under it (its resonance, ω0 = sqrt(g / draught) = 14 rad/s, is well above the wake's
  // 2-5 rad/s, so it follows the surface to within (ω/ω0)² ~ 10 %).
  const scene::Scene s = shipped_scene("default", {"vehicles=[" + kBoat + "]"});
  world::WakeHeights w(wakes_of(s), 128);
  const physics::TriangleMesh hull = box(glm::dvec3(0.25, 0.05, 0.25));
  physics::FloatingBody body(hull, physics::solid_mass_properties(hull, 500.0), {.linear = 1.0}, {});
  body.place(glm::dvec3(10, 0, 4), glm::dquat(1, 0, 0, 0));
  body.settle_vertically(0.0);
  const double rest = body.state().position.y, dt = 1.0 / 120;
  std::vector<double> heave, wake;
  for (int i = 0; i < int(20.0 / dt); ++i) {
    const double t = i * dt;
    w.advance(t, glm::dvec2(0.0));
    body.step(dt, [&w](double x, double z) { return w.height({x, z}); });
    if (t < 6) continue;
    heave.push_back(body.state().position.y - rest);
    wake.push_back(w.height({body.state().position.x, body.state().position.z}));
  }
  double sxy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < heave.size(); ++i) {
    sxy += heave[i] * wake[i];
    sxx += heave[i] * heave[i];
    syy += wake[i] * wake[i];
  }
  const double correlation = sxy / std::sqrt(sxx * syy), ratio = std::sqrt(sxx / syy);
  RecordProperty("correlation", std::to_string(correlation));
  RecordProperty("heave_over_wake_rms", std::to_string(ratio));
  ASSERT_GT(std::sqrt(syy / wake.size()), 0.01) << "no wake reached the box";
  EXPECT_GT(correlation, 0.9);
  EXPECT_NEAR(ratio, 1.0, 0.2);
}

TEST(WakeHeights, AFloatingBuoyFeelsTheBoatOnlyOnceItsWakeArrives) {
  const std::string buoy =
      R"(objects=[{"name":"buoy","file":"assets/buoy.gltf","position":[10,0,12],"floating":{"enabled":true,)"
      R"("density_kg_m3":400,"centre_of_mass_offset":[0,-0.6,0],"linear_damping":2}}])";
  auto run = [&](bool felt) {
    const scene::Scene s = shipped_scene(
        "default",
        {buoy, "vehicles=[" + kBoat + "]", std::string("wakes.felt_by_bodies=") + (felt ? "true" : "false")});
    auto floating = world::FloatingObjects::create(s, s.ocean, ocean::make_cascade_spectra(s.ocean));
    EXPECT_TRUE(floating) << floating.error().message;
    std::vector<double> y;
    for (int i = 0; i <= 80; ++i) {
      (*floating)->advance(0.25 * i);
      y.push_back((*floating)->body(0)->model_origin().y);
    }
    return y;
  };
  const std::vector<double> with = run(true), without = run(false);
  // The boat passes x = 10 at t = 8 s, 18 m from the buoy; its wake's fastest waves (group speed at most
  // half the boat's) need well over 5 s to get there.
  double early = 0, late = 0;
  for (size_t i = 0; i < with.size(); ++i) {
    const double d = std::abs(with[i] - without[i]);
    (0.25 * i <= 5.0 ? early : late) = std::max(0.25 * i <= 5.0 ? early : late, d);
  }
  RecordProperty("largest_difference_before_5s_m", std::to_string(early));
  RecordProperty("largest_difference_after_5s_m", std::to_string(late));
  EXPECT_LT(early, 0.005);
  EXPECT_GT(late, 0.05);
}

}  // namespace
}  // namespace lagoon::test
