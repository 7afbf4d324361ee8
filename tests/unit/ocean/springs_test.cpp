// Model springs (ocean/springs.h; seed 001 §1.1.3, eqs. 4-5, issue 15), the CPU double reference, checked
// against physics it does not compute: the energy decays at exp(-γ t / m); a ring spreads at sqrt(c/m) node
// spacings per second (sqrt(c (1 - L/h) / m) with a rest length); the step is stable just below
// 2 / sqrt(8 c / m) and not just above; the driven column follows its sine; WaveQuery answers the grid.
#include "ocean/springs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/validate.h"
#include "ocean/wave_query.h"

namespace lagoon::test {
namespace {

// A periodic grid of `n` nodes 1 m apart, one drop at the centre at t = 0.
ocean::OceanParams springs_ocean(uint32_t n, double radius_m) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Springs;
  p.choppiness = 0;
  p.cascades = {{double(n), n}};
  p.springs.drops = {{.x_m = n / 2.0, .z_m = n / 2.0, .time_s = 0, .radius_m = radius_m, .speed_mps = 1}};
  return p;
}

double mean_square_height(const ocean::SpringGrid& g) {
  double m = 0;
  for (const glm::dvec2& s : g.state()) m += s.x * s.x;
  return m / double(g.state().size());
}

TEST(Springs, EnergyDecaysAtTheRateDampingSets) {
  const ocean::OceanParams p = springs_ocean(64, 3);
  ocean::SpringGrid grid(p);
  // The energy swings a little between kinetic and potential within a step; averages over 25 steps smooth it.
  auto mean_energy = [&](uint64_t from) {
    grid.advance_to(from);
    double sum = 0;
    for (int k = 0; k < 25; ++k, grid.step()) sum += grid.energy();
    return sum / 25;
  };
  const double e1 = mean_energy(50), e2 = mean_energy(550);
  const double rate = std::log(e1 / e2) / (500 * p.springs.step_s);
  const double expected = p.springs.damping_kg_per_s / p.springs.mass_kg;  // 0.0125 /s
  RecordProperty("energy_decay_per_s", std::to_string(rate));
  EXPECT_NEAR(rate, expected, 0.05 * expected);
}

// The radius of the ring (the largest |h| along +x from the drop, refined by a parabola) at `time_s`.
double ring_radius(ocean::SpringGrid& grid, double time_s, double expected_radius) {
  const std::vector<glm::dvec2> s = grid.surface_at(time_s);
  const uint32_t n = grid.resolution(), c = n / 2;
  auto h = [&](uint32_t i) { return std::abs(s[size_t{c} * n + i].x); };
  uint32_t best = c + uint32_t(expected_radius * 0.6);
  for (uint32_t i = best; i < std::min<uint32_t>(n - 1, c + uint32_t(expected_radius * 1.4)); ++i)
    if (h(i) > h(best)) best = i;
  const double a = h(best - 1), b = h(best), d = h(best + 1);
  return double(best) + 0.5 * (a - d) / (a - 2 * b + d) - c;
}

class SpringsRing : public testing::TestWithParam<double> {};

TEST_P(SpringsRing, SpreadsAtTheSpeedTheSpringsSet) {
  ocean::OceanParams p = springs_ocean(256, 3);
  p.springs.rest_length = GetParam();
  ocean::SpringGrid grid(p);
  // Linearised eq. 4: stiffness c (1 - L/h) per spring; the long waves travel at sqrt of it over m.
  const double speed = std::sqrt(p.springs.stiffness_n_per_m * (1 - GetParam()) / p.springs.mass_kg);
  const double t1 = 40, t2 = 80;
  const double r1 = ring_radius(grid, t1, speed * t1), r2 = ring_radius(grid, t2, speed * t2);
  const double measured = (r2 - r1) / (t2 - t1);
  RecordProperty("ring_speed_cells_per_s", std::to_string(measured));
  RecordProperty("expected_cells_per_s", std::to_string(speed));
  EXPECT_NEAR(measured, speed, 0.05 * speed) << "radii " << r1 << ", " << r2;
}

INSTANTIATE_TEST_SUITE_P(RestLengths, SpringsRing, testing::Values(0.0, 0.5));

TEST(Springs, StableJustBelowTheLimitAndNotJustAbove) {
  // A drop narrower than a cell excites the checkerboard, the stiffest mode.
  ocean::OceanParams p = springs_ocean(64, 0.3);
  p.springs.damping_kg_per_s = 0;
  const double limit = ocean::springs_stability_limit_s(p.springs);
  EXPECT_NEAR(limit, 2 / std::sqrt(8 * 7.0 / 4.0), 1e-12);
  for (double factor : {0.98, 1.02}) {
    p.springs.step_s = factor * limit;
    ocean::SpringGrid grid(p);
    // The mean square height over a window of steps, late against early: near 1 while stable.
    auto window_max = [&](uint64_t from) {
      double m = 0;
      for (grid.advance_to(from); grid.steps() < from + 50; grid.step()) m += mean_square_height(grid);
      return m;
    };
    const double early = window_max(100);
    const double growth = window_max(1000) / early;
    RecordProperty("growth_at_" + std::to_string(factor), std::to_string(growth));
    if (factor < 1)
      EXPECT_NEAR(growth, 1.0, 0.1);
    else
      EXPECT_GT(growth, 1e3);
  }
  p.springs.step_s = 1.02 * limit;
  const Result<void> refused = ocean::validate(p);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("springs.step_s"), std::string::npos) << refused.error().message;
  EXPECT_NE(refused.error().message.find("stability limit"), std::string::npos) << refused.error().message;
}

TEST(Springs, ADropMovesNoNetWater) {
  // Without the excitation's mean taken off, this drop would sink the 64 m grid by 8 mm a second for good.
  ocean::SpringGrid grid(springs_ocean(64, 3));
  grid.advance_to(200);
  double mean = 0, largest = 0;
  for (const glm::dvec2& s : grid.state()) {
    mean += s.x / double(grid.state().size());
    largest = std::max(largest, std::abs(s.x));
  }
  EXPECT_LT(std::abs(mean), 1e-6 * largest) << "largest height " << largest;
}

TEST(Springs, TheDrivenColumnFollowsItsSineAndSendsWaves) {
  ocean::OceanParams p = springs_ocean(64, 3);
  p.springs.drops.clear();
  p.springs.boundary_amplitude_m = 0.5;
  p.springs.boundary_period_s = 6;
  ocean::SpringGrid grid(p);
  grid.advance_to(100);
  const double t = 100 * p.springs.step_s, omega = 2 * std::numbers::pi / 6;
  for (uint32_t j = 0; j < 64; j += 7)
    EXPECT_NEAR(grid.state()[size_t{j} * 64].x, 0.5 * std::sin(omega * t), 1e-12);
  // 10 cells away the waves have arrived (sqrt(7/4) = 1.32 cells/s: after 7.6 s of the 40).
  EXPECT_GT(std::abs(grid.state()[size_t{20} * 64 + 10].x), 0.05);
}

TEST(Springs, WaveQueryAnswersTheGridAtItsNodes) {
  ocean::OceanParams p = springs_ocean(64, 3);
  ocean::SpringGrid grid(p);
  ocean::WaveQuery query(p);
  const double t = 17.3;  // between steps 43 and 44: the line between them
  const std::vector<glm::dvec2> s = grid.surface_at(t);
  EXPECT_EQ(grid.steps(), 44u);
  double worst = 0;
  for (uint32_t j = 20; j < 44; j += 3)
    for (uint32_t i = 20; i < 44; i += 5) {
      const ocean::WaveSample w = query.sample(t, i, j);
      worst = std::max(worst, std::abs(w.height - s[size_t{j} * 64 + i].x));
      EXPECT_NEAR(w.velocity.y, s[size_t{j} * 64 + i].y, 1e-12);
      const double sx = (s[size_t{j} * 64 + i + 1].x - s[size_t{j} * 64 + i - 1].x) / 2;
      EXPECT_NEAR(w.normal.x,
                  -sx / glm::length(glm::dvec3(
                            -sx, 1, -(s[size_t{j + 1} * 64 + i].x - s[size_t{j - 1} * 64 + i].x) / 2)),
                  1e-12);
    }
  EXPECT_LT(worst, 1e-12);
  // x_44 - v_44 (t_44 - t) is the straight line from x_43: at t_43 it is x_43.
  ocean::SpringGrid at43(p);
  at43.advance_to(43);
  const std::vector<glm::dvec2> line = grid.surface_at(43 * p.springs.step_s);
  for (size_t i = 0; i < line.size(); i += 97) EXPECT_NEAR(line[i].x, at43.state()[i].x, 1e-12);
}

}  // namespace
}  // namespace lagoon::test
