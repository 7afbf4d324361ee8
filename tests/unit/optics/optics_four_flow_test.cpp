// The four-flow closed form (compute/optics/four_flow) against an independent numerical solution of the
// same boundary-value problem, against eq. 4 itself (finite differences) and eq. 7, and in its limits:
// deep water, depth 0, no scattering, vanishing absorption, λ0 → 1, and the energy balance.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "optics/four_flow.h"
#include "support/four_flow_reference.h"

namespace lagoon::optics {
namespace {

using Flows = std::array<double, 4>;  // G+, G−, F+, F−

Flows flows_at(const FourFlowSolution& s, double tau) {
  return {s.g_plus(tau), s.g_minus(tau), s.f_plus(tau), s.f_minus(tau)};
}

// Portable seeded uniforms (std distributions differ between standard libraries).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  double uniform(double a, double b) { return a + (b - a) * double(engine_() >> 11) * 0x1p-53; }
  double log_uniform(double a, double b) { return a * std::pow(b / a, uniform(0, 1)); }

  // Three numbers >= 0 summing to at most 1: a partition of 1 with a remainder.
  std::array<double, 3> partition() {
    double c1 = uniform(0, 1), c2 = uniform(0, 1), c3 = uniform(0, 1);
    if (c1 > c2) std::swap(c1, c2);
    if (c2 > c3) std::swap(c2, c3);
    if (c1 > c2) std::swap(c1, c2);
    return {c1, c2 - c1, c3 - c2};
  }

 private:
  std::mt19937_64 engine_;
};

// Random surface, bottom and light consistent with eq. 6.
FourFlowInput random_boundaries(Rng& rng) {
  FourFlowInput in{};
  const auto [t_dd, r_dd, t_df] = rng.partition();
  in.surface.t_dd = t_dd;
  in.surface.r_dd = r_dd;
  in.surface.t_df = t_df;
  in.surface.r_df = 1.0 - t_dd - r_dd - t_df;
  in.surface.r_ff = rng.uniform(0, 1);
  in.surface.t_ff = 1.0 - in.surface.r_ff;
  const auto [rw_dd, rw_df, unused] = rng.partition();
  in.surface.rw_dd = rw_dd;
  in.surface.rw_df = rw_df;
  in.surface.rw_ff = rng.uniform(0, 1);
  in.surface.tw_ff = 1.0 - in.surface.rw_ff;
  const auto [b_dd, b_df, absorbed] = rng.partition();
  in.bottom = {.r_dd = b_dd, .r_df = b_df, .r_ff = rng.uniform(0, 1)};
  in.e_sun = rng.uniform(0, 2);
  in.e_sky = rng.uniform(0, 2);
  return in;
}

FourFlowInput random_input(Rng& rng, double max_x1) {
  FourFlowInput in = random_boundaries(rng);
  in.absorption_per_m = rng.log_uniform(0.01, 10);
  const double pick_sigma = rng.uniform(0, 1);
  in.scattering_per_m = pick_sigma < 0.1    ? 0.0
                        : pick_sigma < 0.55 ? rng.log_uniform(1e-4, 10)
                                            : rng.uniform(0, 10);
  in.phase_x1 = rng.uniform(0, max_x1);
  const double pick_depth = rng.uniform(0, 1);
  in.depth_m = pick_depth < 0.05 ? 0.0 : pick_depth < 0.5 ? rng.log_uniform(1e-3, 100) : rng.uniform(0, 100);
  // Half the cases with a diffuse path-length factor (the seed's D = 1 in the others).
  in.diffuse_path_factor = rng.uniform(0, 1) < 0.5 ? 1.0 : rng.uniform(1, 3);
  return in;
}

bool well_posed(const FourFlowInput& in) {
  return in.absorption_per_m + in.scattering_per_m * (2 - in.phase_x1) > 0;
}

std::string describe(const FourFlowInput& in) {
  return "chi=" + std::to_string(in.absorption_per_m) + " sigma=" + std::to_string(in.scattering_per_m) +
         " x1=" + std::to_string(in.phase_x1) + " h=" + std::to_string(in.depth_m);
}

// Relative difference; below 1e-250 of the incoming light both solvers are in the denormal range.
double relative_error(double value, double reference, double light) {
  return std::fabs(value - reference) / std::max(std::fabs(reference), 1e-250 * light);
}

TEST(FourFlowReference, ClosedFormMatchesMultipleShooting) {
  Rng rng(20240611);
  double worst = 0;
  std::string worst_case;
  int solved = 0, ill_posed = 0;
  for (int n = 0; n < 600; ++n) {
    const FourFlowInput in = random_input(rng, 2.5);
    Result<FourFlowSolution> s = solve_four_flow(in);
    if (!well_posed(in)) {
      ASSERT_FALSE(s.ok()) << describe(in);
      EXPECT_NE(s.error().message.find("phase_x1"), std::string::npos);
      ++ill_posed;
      continue;
    }
    ASSERT_TRUE(s.ok()) << describe(in) << ": " << s.error().message;
    ++solved;
    const test::FourFlowProfile ref = test::solve_four_flow_reference(in);
    const int last = int(ref.flow.size()) - 1;
    const double light = in.e_sun + in.e_sky;
    for (int node : {0, last / 2, last}) {
      const Flows got = flows_at(*s, node == last ? s->tau0 : node * ref.step);
      for (int c = 0; c < 4; ++c) {
        const double err = relative_error(got[c], ref.flow[node][c], light);
        EXPECT_LE(err, 1e-6) << describe(in) << " node " << node << "/" << last << " flow " << c << ": "
                             << got[c] << " vs " << ref.flow[node][c];
        if (err > worst) {
          worst = err;
          worst_case = describe(in) + " flow " + std::to_string(c) + " node " + std::to_string(node);
        }
      }
    }
  }
  std::printf("[ info ] %d cases solved, %d ill-posed rejected; worst relative error %.3g (%s)\n", solved,
              ill_posed, worst, worst_case.c_str());
  EXPECT_GT(solved, 450);
}

TEST(FourFlowReference, LambdaZeroNearOne) {
  // σ → 0 with X1 = 0: λ0 → 1, where the seed's A1, A2 have a 0/0 and its closed form loses precision.
  Rng rng(7);
  for (double ratio : {1e-12, 1e-9, 1e-7, 1e-5, 1e-3}) {
    for (double x1 : {0.0, 1e-6, 0.5}) {
      FourFlowInput in = random_boundaries(rng);
      in.absorption_per_m = 0.5;
      in.scattering_per_m = 0.5 * ratio;
      in.phase_x1 = x1;
      in.depth_m = 7;
      Result<FourFlowSolution> s = solve_four_flow(in);
      ASSERT_TRUE(s.ok());
      const test::FourFlowProfile ref = test::solve_four_flow_reference(in);
      const int last = int(ref.flow.size()) - 1;
      for (int node : {0, last / 2, last}) {
        const Flows got = flows_at(*s, node == last ? s->tau0 : node * ref.step);
        for (int c = 0; c < 4; ++c)
          EXPECT_LE(relative_error(got[c], ref.flow[node][c], in.e_sun + in.e_sky), 1e-6)
              << describe(in) << " flow " << c << " node " << node;
      }
    }
  }
}

TEST(FourFlowResidual, SatisfiesEquation4) {
  Rng rng(99);
  int checked = 0;
  while (checked < 200) {
    const FourFlowInput in = random_input(rng, 2.5);
    Result<FourFlowSolution> s = solve_four_flow(in);
    if (!s || s->tau0 < 1e-3) continue;
    ++checked;
    const FourFlowSolution& f = *s;
    for (double frac : {0.1, 0.37, 0.5, 0.81}) {
      const double tau = frac * f.tau0, h = std::min(1e-3, 0.05 * tau);
      const Flows a = flows_at(f, tau - h), b = flows_at(f, tau + h), y = flows_at(f, tau);
      // Right-hand side of eq. 4, each term kept for the scale of the residual.
      const std::array<std::array<double, 4>, 4> terms = {{
          {-f.lambda * y[0], 0, 0, 0},
          {f.lambda * y[1], 0, 0, 0},
          {-f.diffuse_path * (f.k + f.s) * y[2], f.diffuse_path * f.s * y[3], f.s1 * y[0], f.s2 * y[1]},
          {f.diffuse_path * (f.k + f.s) * y[3], -f.diffuse_path * f.s * y[2], -f.s1 * y[1], -f.s2 * y[0]},
      }};
      for (int c = 0; c < 4; ++c) {
        const double derivative = (b[c] - a[c]) / (2 * h);
        double rhs = 0, scale = std::fabs(derivative);
        for (double t : terms[c]) {
          rhs += t;
          scale += std::fabs(t);
        }
        if (scale < 1e-250) continue;
        EXPECT_LE(std::fabs(derivative - rhs), 1e-6 * scale) << describe(in) << " τ=" << tau << " flow " << c;
      }
    }
  }
}

TEST(FourFlowBoundary, SatisfiesEquation7) {
  Rng rng(1234);
  int checked = 0;
  while (checked < 300) {
    const FourFlowInput in = random_input(rng, 2.5);
    Result<FourFlowSolution> s = solve_four_flow(in);
    if (!s) continue;
    ++checked;
    const Flows top = flows_at(*s, 0), bottom = flows_at(*s, s->tau0);
    const SurfaceCoefficients& c = in.surface;
    const BottomCoefficients& b = in.bottom;
    const double light = in.e_sun + in.e_sky, tol = 1e-12;
    EXPECT_NEAR(top[0], c.t_dd * in.e_sun + c.rw_dd * top[1], tol * light) << describe(in);
    EXPECT_NEAR(top[2], c.t_df * in.e_sun + c.t_ff * in.e_sky + c.rw_df * top[1] + c.rw_ff * top[3],
                tol * light)
        << describe(in);
    EXPECT_NEAR(bottom[1], b.r_dd * bottom[0], tol * std::max(bottom[0], 1e-250)) << describe(in);
    EXPECT_NEAR(bottom[3], b.r_df * bottom[0] + b.r_ff * bottom[2], tol * std::max(bottom[3], 1e-250))
        << describe(in);
  }
}

FourFlowInput water(double chi, double sigma, double x1, double depth, double albedo) {
  FourFlowInput in{};
  in.absorption_per_m = chi;
  in.scattering_per_m = sigma;
  in.phase_x1 = x1;
  in.depth_m = depth;
  in.surface = surface_coefficients(1.333, 0.6);
  in.bottom = lambertian_bottom(albedo);
  in.e_sun = 1.0;
  in.e_sky = 0.25;
  return in;
}

TEST(FourFlowLimits, DeepWaterHidesTheBottom) {
  // χ = σ = 1 /m, X1 = 0.5: λ0 = sqrt(0.5 · 1.25) = 0.79, so the bottom's share of F−(0) is ~e^{−2·50·0.79}.
  for (double x1 : {0.0, 0.5, 1.0, 2.2}) {
    const double eps = 2.0, h = 50.0 / eps;
    Result<FourFlowSolution> black = solve_four_flow(water(1, 1, x1, h, 0.0));
    Result<FourFlowSolution> white = solve_four_flow(water(1, 1, x1, h, 1.0));
    ASSERT_TRUE(black.ok() && white.ok());
    EXPECT_DOUBLE_EQ(black->tau0, 50.0);
    EXPECT_NEAR(black->f_minus(0), white->f_minus(0), 1e-9 * std::fabs(black->f_minus(0))) << x1;
    // X1 > 1 makes S2 < 0, a sink of F− fed by G+: here F−(0) comes out negative (see four_flow.h).
    if (x1 <= 1) {
      EXPECT_GT(black->f_minus(0), 0.0);
    }
  }
}

TEST(FourFlowLimits, HugeOpticalDepthsStayFiniteAndExact) {
  Result<FourFlowSolution> deep = solve_four_flow(water(0.1, 0.3, 0.8, 400, 0.5));  // τ0 = 160
  ASSERT_TRUE(deep.ok());
  for (double depth : {2.5e4, 1e6, 1e12}) {  // τ0 = 1e4, 4e5, 4e11
    for (double albedo : {0.0, 1.0}) {
      Result<FourFlowSolution> s = solve_four_flow(water(0.1, 0.3, 0.8, depth, albedo));
      ASSERT_TRUE(s.ok());
      for (double frac : {0.0, 1e-9, 0.5, 1.0}) {
        for (double v : flows_at(*s, frac * s->tau0)) {
          EXPECT_TRUE(std::isfinite(v)) << depth;
          EXPECT_GE(v, 0.0);
        }
      }
      for (double tau : {0.0, 1.0, 10.0, 100.0}) {
        const Flows a = flows_at(*s, tau), b = flows_at(*deep, tau);
        for (int c = 0; c < 4; ++c)
          EXPECT_NEAR(a[c], b[c], 1e-12 * (std::fabs(b[c]) + 1e-300)) << tau << " " << c;
      }
      EXPECT_EQ(s->g_plus(s->tau0) + s->f_plus(s->tau0), 0.0);  // nothing reaches a bottom that deep
    }
  }
}

TEST(FourFlowLimits, DepthZeroIsTheBottomSeenThroughTheSurface) {
  Rng rng(5);
  for (int n = 0; n < 50; ++n) {
    FourFlowInput in = random_boundaries(rng);
    in.absorption_per_m = rng.log_uniform(0.01, 10);
    in.scattering_per_m = rng.uniform(0, 10);
    in.phase_x1 = rng.uniform(0, 2);
    in.depth_m = 0;
    Result<FourFlowSolution> s = solve_four_flow(in);
    ASSERT_TRUE(s.ok());
    const SurfaceCoefficients& c = in.surface;
    const BottomCoefficients& b = in.bottom;
    // Light bounces between surface and bottom without passing any water.
    const double g_plus = c.t_dd * in.e_sun / (1 - c.rw_dd * b.r_dd), g_minus = b.r_dd * g_plus;
    const double f_down_source = c.t_df * in.e_sun + c.t_ff * in.e_sky + c.rw_df * g_minus;
    const double f_minus = (b.r_df * g_plus + b.r_ff * f_down_source) / (1 - b.r_ff * c.rw_ff);
    const double scale = in.e_sun + in.e_sky;
    EXPECT_NEAR(s->f_minus(0), f_minus, 1e-13 * scale);
    EXPECT_NEAR(s->g_plus(0), g_plus, 1e-13 * scale);
    EXPECT_NEAR(s->g_minus(0), g_minus, 1e-13 * scale);
    EXPECT_NEAR(s->f_plus(0), f_down_source + c.rw_ff * f_minus, 1e-13 * scale);
  }
  // The flat surface and a Lambertian bottom: F−(0) = A (T_dd E_sun + T_ff E_sky) / (1 − A R̃_ff).
  const FourFlowInput in = water(0.2, 0.1, 0.5, 0.0, 0.3);
  Result<FourFlowSolution> s = solve_four_flow(in);
  ASSERT_TRUE(s.ok());
  const double expected =
      0.3 * (in.surface.t_dd * in.e_sun + in.surface.t_ff * in.e_sky) / (1 - 0.3 * in.surface.rw_ff);
  EXPECT_NEAR(s->f_minus(0), expected, 1e-15);
  EXPECT_NEAR(s->g_plus(0) + s->f_plus(0), (s->f_minus(0)) / 0.3, 1e-15);
}

TEST(FourFlowLimits, NoScatteringLeavesOnlyBottomLight) {
  Rng rng(11);
  for (int n = 0; n < 50; ++n) {
    FourFlowInput in = random_boundaries(rng);
    in.absorption_per_m = rng.log_uniform(0.01, 10);
    in.scattering_per_m = 0;
    in.phase_x1 = rng.uniform(0, 2.9);
    in.depth_m = rng.log_uniform(1e-3, 10);
    Result<FourFlowSolution> s = solve_four_flow(in);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->lambda0, 1.0);
    const SurfaceCoefficients& c = in.surface;
    const BottomCoefficients& b = in.bottom;
    // Each flow only attenuates, e^{−τ}; they meet only at the boundaries.
    const double t0 = s->tau0, d = std::exp(-t0);
    const double g0 = c.t_dd * in.e_sun / (1 - c.rw_dd * b.r_dd * d * d), gh = b.r_dd * d * g0;
    const double top_source = c.t_df * in.e_sun + c.t_ff * in.e_sky + c.rw_df * gh * d;
    const double f0 = (top_source + c.rw_ff * d * b.r_df * g0 * d) / (1 - c.rw_ff * b.r_ff * d * d);  // F+(0)
    const double fh = b.r_df * g0 * d + b.r_ff * f0 * d;  // F−(τ0)
    for (double tau : {0.0, 0.3 * t0, t0}) {
      const double scale = (in.e_sun + in.e_sky) * 1e-13;
      EXPECT_NEAR(s->g_plus(tau), g0 * std::exp(-tau), scale);
      EXPECT_NEAR(s->g_minus(tau), gh * std::exp(tau - t0), scale);
      EXPECT_NEAR(s->f_plus(tau), f0 * std::exp(-tau), scale);
      EXPECT_NEAR(s->f_minus(tau), fh * std::exp(tau - t0), scale);
    }
  }
  // Flat surface, no sky: G+ = t_dd E_sun e^{−τ}, and all diffuse light comes off the bottom.
  FourFlowInput in = water(0.3, 0.0, 0.0, 2.0, 0.4);
  in.e_sky = 0;
  Result<FourFlowSolution> s = solve_four_flow(in);
  ASSERT_TRUE(s.ok());
  const double d = std::exp(-s->tau0);
  for (double tau : {0.0, 0.2, 0.6}) EXPECT_NEAR(s->g_plus(tau), in.surface.t_dd * std::exp(-tau), 1e-15);
  EXPECT_EQ(s->g_minus(0), 0.0);
  const double f_minus0 = 0.4 * in.surface.t_dd * d * d / (1 - 0.4 * in.surface.rw_ff * d * d);
  EXPECT_NEAR(s->f_minus(0), f_minus0, 1e-15);
  EXPECT_NEAR(s->f_plus(0), in.surface.rw_ff * f_minus0, 1e-15);
}

// Light in = light reflected at the surface + light escaping upwards + absorbed by the bottom + absorbed by
// the water; the last is k ∫ (G+ + G− + F+ + F−) dτ (sum eq. 4's lines with signs +, −, +, −).
struct EnergyBudget {
  double in, reflected, escaped, bottom, water;
};

EnergyBudget energy_budget(const FourFlowInput& in, const FourFlowSolution& s) {
  const SurfaceCoefficients& c = in.surface;
  const BottomCoefficients& b = in.bottom;
  EnergyBudget e{};
  e.in = in.e_sun + in.e_sky;
  e.reflected = (c.r_dd + c.r_df) * in.e_sun + c.r_ff * in.e_sky;
  e.escaped = (1 - c.rw_dd - c.rw_df) * s.g_minus(0) + c.tw_ff * s.f_minus(0);
  e.bottom = (1 - b.r_dd - b.r_df) * s.g_plus(s.tau0) + (1 - b.r_ff) * s.f_plus(s.tau0);
  // Composite Simpson; the integrand varies on scales >= 1/(1 + 2|S|) optical depths.
  const int n = 20000;
  const double h = s.tau0 / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const Flows f = flows_at(s, i * h);
    sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * (f[0] + f[1] + f[2] + f[3]);
  }
  e.water = s.k * sum * h / 3;
  return e;
}

TEST(FourFlowLimits, EnergyIsConserved) {
  Rng rng(3);
  for (int n = 0; n < 100; ++n) {
    FourFlowInput in = random_boundaries(rng);
    in.absorption_per_m = rng.log_uniform(0.01, 10);
    in.scattering_per_m = rng.log_uniform(1e-3, 10);
    in.phase_x1 = rng.uniform(0, 2.5);
    in.depth_m = rng.uniform(0, 20 / (in.absorption_per_m + in.scattering_per_m));  // τ0 <= 20
    Result<FourFlowSolution> s = solve_four_flow(in);
    if (!s) continue;
    const EnergyBudget e = energy_budget(in, *s);
    EXPECT_NEAR(e.reflected + e.escaped + e.bottom + e.water, e.in, 1e-9 * e.in) << describe(in);
  }
}

TEST(FourFlowLimits, NoAbsorptionLosesNothingInTheWater) {
  // χ → 0: only the surface and the bottom take light out. With σ = 0 the layer is also optically thin; with
  // σ > 0 it is thick (τ0 = 10) and nearly conservative: λ0 ≈ 4e-5, the diffusion limit, where the two
  // diffuse modes become parallel (A3 → 1) and the closed form keeps ~ 1e-16/λ0² relative precision.
  for (double sigma : {0.0, 1.0}) {
    for (double albedo : {0.0, 0.5, 1.0}) {
      const FourFlowInput in = water(1e-9, sigma, 0.6, 10.0, albedo);
      Result<FourFlowSolution> s = solve_four_flow(in);
      ASSERT_TRUE(s.ok());
      const EnergyBudget e = energy_budget(in, *s);
      EXPECT_LT(e.water, 1e-6 * e.in);
      EXPECT_NEAR(e.reflected + e.escaped + e.bottom, e.in, 1e-6 * e.in) << sigma << " " << albedo;
      EXPECT_NEAR(e.reflected + e.escaped + e.bottom + e.water, e.in, (sigma > 0 ? 1e-7 : 1e-14) * e.in)
          << sigma << " " << albedo;
    }
  }
}

TEST(FourFlowLimits, NonNegativeForPhysicalPhaseFunctions) {
  // X1 <= 1 makes every coupling in eq. 4 non-negative, so the exact flows are >= 0; the reference
  // (not clamped) confirms it, and the closed form agrees.
  Rng rng(77);
  for (int n = 0; n < 100; ++n) {
    const FourFlowInput in = random_input(rng, 1.0);
    Result<FourFlowSolution> s = solve_four_flow(in);
    ASSERT_TRUE(s.ok());
    const test::FourFlowProfile ref = test::solve_four_flow_reference(in);
    for (size_t i = 0; i < ref.flow.size(); i += std::max<size_t>(1, ref.flow.size() / 37)) {
      const Flows got = flows_at(*s, double(i) * ref.step);
      for (int c = 0; c < 4; ++c) {
        EXPECT_GE(got[c], 0.0);
        EXPECT_GE(ref.flow[i][c], -1e-12 * (in.e_sun + in.e_sky)) << describe(in);
      }
    }
  }
}

TEST(FourFlowValidation, RejectsInvalidInputNamingTheParameter) {
  auto message = [](FourFlowInput in) {
    Result<FourFlowSolution> s = solve_four_flow(in);
    return s.ok() ? std::string("ok") : s.error().message;
  };
  const FourFlowInput good = water(0.1, 0.2, 0.5, 3, 0.3);
  EXPECT_EQ(message(good), "ok");
  auto with = [&](auto change) {
    FourFlowInput in = good;
    change(in);
    return message(in);
  };
  EXPECT_NE(with([](auto& in) { in.absorption_per_m = 0; }).find("absorption_per_m"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.absorption_per_m = NAN; }).find("absorption_per_m"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.scattering_per_m = -1e-9; }).find("scattering_per_m"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.scattering_per_m = INFINITY; }).find("scattering_per_m"),
            std::string::npos);
  EXPECT_NE(with([](auto& in) { in.phase_x1 = -0.1; }).find("phase_x1"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.phase_x1 = 3.0; }).find("phase_x1"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.depth_m = -1; }).find("depth_m"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.surface.rw_ff = 1.5; }).find("surface"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.bottom.r_ff = -0.1; }).find("bottom"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.e_sun = NAN; }).find("e_sun"), std::string::npos);
  EXPECT_NE(with([](auto& in) { in.e_sky = -1; }).find("e_sky"), std::string::npos);
  // X1 > 2 with σ(X1 − 2) >= χ: no bounded solution (the seed's S < 0 makes λ0² <= 0).
  EXPECT_NE(with([](auto& in) {
              in.phase_x1 = 2.75, in.scattering_per_m = 0.2, in.absorption_per_m = 0.1;
            }).find("phase_x1"),
            std::string::npos);
  EXPECT_EQ(with([](auto& in) { in.phase_x1 = 2.75, in.scattering_per_m = 0.2, in.absorption_per_m = 0.16; }),
            "ok");
  // Depth 0 between perfect mirrors: light bounces forever.
  EXPECT_NE(with([](auto& in) {
              in.depth_m = 0;
              in.surface.rw_ff = 1, in.surface.tw_ff = 0, in.bottom.r_ff = 1;
            }).find("lossless"),
            std::string::npos);
}

}  // namespace
}  // namespace lagoon::optics
