// Gerstner waves (ocean/gerstner.h; seed 001 eqs. 6-11, issue 15): a single wave is the closed-form trochoid,
// its crests are sharper than its troughs by the trochoid's curvature ratio, no wave set loops while
// Σ Q k A <= 1 (and one does beyond), each dispersion law gives its phase speed, eq. 10 makes the surface
// periodic, and the normal and velocity are the derivatives of the surface.
#include "ocean/gerstner.h"
#include "support/reference_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <numbers>

namespace lagoon::test {
namespace {

using ocean::GerstnerDispersion;
using ocean::GerstnerParams;
using ocean::GerstnerSurface;
using ocean::GerstnerWave;

// The root of a function increasing over [a, b], by bisection.
double bisect(const std::function<double(double)>& f, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    (f(m) < 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// The x maximising f in [a, b] (f unimodal there), by golden section.
double argmax(const std::function<double(double)>& f, double a, double b) {
  const double r = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - r * (b - a), d = a + r * (b - a);
  for (int i = 0; i < 200; ++i) {
    if (f(c) > f(d))
      b = d;
    else
      a = c;
    c = b - r * (b - a);
    d = a + r * (b - a);
  }
  return 0.5 * (a + b);
}

GerstnerSurface single(double amplitude, double wavelength, GerstnerDispersion law = GerstnerDispersion::Deep,
                       double depth = 1000, double phase = 0.2) {
  return GerstnerSurface(GerstnerParams{
      .waves =
          {{.amplitude_m = amplitude, .wavelength_m = wavelength, .direction_deg = 90, .phase_rad = phase}},
      .dispersion = law,
      .depth_m = depth});
}

TEST(Gerstner, ASingleWaveIsTheTrochoid) {
  // Along +x: a circle of radius 1/k rolling, the point A from its centre: x = θ/k - A sin θ + const,
  // y = A cos θ. The height above any x: solve for θ (x is increasing in θ while kA < 1).
  const double a = 0.4, lambda = 10, k = 2 * std::numbers::pi / lambda, w = std::sqrt(kG * k), t = 1.3,
               phi = 0.2;
  const GerstnerSurface s = single(a, lambda);
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    const double x = -23.7 + 0.317 * i;
    const double theta = bisect([&](double th) { return (th + w * t - phi) / k - a * std::sin(th) - x; },
                                k * x - 10, k * x + 10);
    const ocean::WaveSample sample = s.sample(t, x, 4.2);
    ASSERT_TRUE(sample.converged) << x;
    worst = std::max(worst, std::abs(sample.height - a * std::cos(theta)));
  }
  RecordProperty("worst_height_error_m", std::to_string(worst));
  EXPECT_LT(worst, 1e-5);
}

TEST(Gerstner, CrestsAreSharperThanTroughsByTheTrochoidsRatio) {
  // y'' = -A k² / (1 - kA)² at a crest, A k² / (1 + kA)² at a trough: 2.78 times sharper at kA = 0.25.
  const double a = 0.4, lambda = 10, k = 2 * std::numbers::pi / lambda, t = 0.7;
  const GerstnerSurface s = single(a, lambda);
  const auto height = [&](double x) { return s.sample(t, x, 0).height; };
  const double crest = argmax(height, -2, 8),
               trough = argmax([&](double x) { return -height(x); }, crest, crest + 10);
  const double h = 1e-3;
  const auto curvature = [&](double x) { return (height(x + h) - 2 * height(x) + height(x - h)) / (h * h); };
  const double at_crest = curvature(crest), at_trough = curvature(trough);
  RecordProperty("crest_curvature", std::to_string(at_crest));
  RecordProperty("trough_curvature", std::to_string(at_trough));
  EXPECT_NEAR(at_crest, -a * k * k / std::pow(1 - k * a, 2), 1e-3 * std::abs(at_crest));
  EXPECT_NEAR(at_trough, a * k * k / std::pow(1 + k * a, 2), 1e-3 * at_trough);
  EXPECT_GT(-at_crest, 2.5 * at_trough);
}

// The smallest Jacobian of the horizontal map over a 40 m square at t.
double smallest_jacobian(const GerstnerSurface& s, double t) {
  double lowest = 1e9;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i) lowest = std::min(lowest, s.at_rest({0.2 * i, 0.2 * j}, t).jacobian);
  return lowest;
}

TEST(Gerstner, NoLoopsWhileTheSteepnessSumIsAtMostOne) {
  GerstnerParams p;
  // Five waves within 12° of each other, each with k A = 0.32: where their crests meet, the map folds.
  const double lambdas[] = {12, 7, 5, 3.3, 2.1}, dirs[] = {0, 8, -6, 12, -10};
  for (int i = 0; i < 5; ++i)
    p.waves.push_back({.amplitude_m = 0.32 * lambdas[i] / (2 * std::numbers::pi),
                       .wavelength_m = lambdas[i],
                       .direction_deg = dirs[i],
                       .phase_rad = 0.7 * i});
  // Each wave has k A = 0.32: Σ Q k A = 1.6 as given.
  p.limit_steepness = false;
  const GerstnerSurface looping(p);
  EXPECT_NEAR(looping.steepness_sum(), 1.6, 1e-9);
  p.limit_steepness = true;
  const GerstnerSurface limited(p);
  EXPECT_NEAR(limited.steepness_sum(), 1.0, 1e-12);
  double limited_low = 1e9, looping_low = 1e9;
  for (double t : {0.0, 1.7, 4.1, 6.3, 9.9}) {
    limited_low = std::min(limited_low, smallest_jacobian(limited, t));
    looping_low = std::min(looping_low, smallest_jacobian(looping, t));
  }
  RecordProperty("smallest_jacobian_limited", std::to_string(limited_low));
  RecordProperty("smallest_jacobian_unlimited", std::to_string(looping_low));
  EXPECT_GE(limited_low, -1e-12);
  EXPECT_LT(looping_low, -0.05) << "the check could not fail";
}

TEST(Gerstner, EachDispersionLawGivesItsPhaseSpeed) {
  struct Case {
    GerstnerDispersion law;
    double lambda, depth, speed;  // c = ω / k from the law, written out here
  };
  const auto k_of = [](double lambda) { return 2 * std::numbers::pi / lambda; };
  const double sigma_over_rho_g = 0.074 / (1000 * kG);
  const Case cases[] = {
      {GerstnerDispersion::Deep, 30, 1000, std::sqrt(kG / k_of(30))},
      {GerstnerDispersion::FiniteDepth, 20, 2, std::sqrt(kG * std::tanh(k_of(20) * 2) / k_of(20))},
      {GerstnerDispersion::Capillary, 0.01, 1000,
       std::sqrt(kG / k_of(0.01) * (1 + k_of(0.01) * k_of(0.01) * sigma_over_rho_g))},
  };
  for (const Case& c : cases) {
    const double a = 0.05 * c.lambda;
    const GerstnerSurface s = single(a, c.lambda, c.law, c.depth, 0.0);
    const auto crest_at = [&](double t) {
      const double guess = c.speed * t;  // θ = 0 there
      return argmax([&](double x) { return s.sample(t, x, 0).height; }, guess - 0.3 * c.lambda,
                    guess + 0.3 * c.lambda);
    };
    const double dt = 0.05 * c.lambda / c.speed;
    const double measured = (crest_at(1.0 + dt) - crest_at(1.0)) / dt;
    EXPECT_NEAR(measured, c.speed, 1e-4 * c.speed) << "lambda " << c.lambda;
  }
  // Finite depth slows the wave: 2 m of water against deep water for the same 20 m wave.
  EXPECT_LT(cases[1].speed, 0.8 * std::sqrt(kG / k_of(20)));
}

TEST(Gerstner, ALoopPeriodMakesTheSurfaceRepeat) {
  GerstnerParams p{.waves = {{.amplitude_m = 0.3, .wavelength_m = 9, .direction_deg = 30},
                             {.amplitude_m = 0.1, .wavelength_m = 3.7, .direction_deg = -50, .phase_rad = 1}},
                   .loop_period_s = 12};
  const GerstnerSurface s(p);
  for (size_t i = 0; i < s.size(); ++i) {
    const double cycles = s.omega(i) * 12 / (2 * std::numbers::pi);
    EXPECT_NEAR(cycles, std::round(cycles), 1e-9);
  }
  for (double x : {0.3, 5.1, -7.7})
    EXPECT_NEAR(s.sample(2.5, x, 1.1).height, s.sample(14.5, x, 1.1).height, 1e-9);
  p.loop_period_s = 0;
  EXPECT_GT(std::abs(GerstnerSurface(p).sample(2.5, 0.3, 1.1).height -
                     GerstnerSurface(p).sample(14.5, 0.3, 1.1).height),
            1e-3);
}

TEST(Gerstner, NormalAndVelocityAreTheSurfacesDerivatives) {
  GerstnerParams p{
      .waves = {{.amplitude_m = 0.3, .wavelength_m = 9, .direction_deg = 30, .steepness = 0.8},
                {.amplitude_m = 0.1, .wavelength_m = 3.7, .direction_deg = -50, .phase_rad = 1}}};
  const GerstnerSurface s(p);
  const double t = 3.3, e = 1e-5;
  for (glm::dvec2 q : {glm::dvec2(0.4, 1.9), glm::dvec2(-3.1, 7.2), glm::dvec2(11.0, -2.5)}) {
    const ocean::WaveSample at = s.sample(t, q.x, q.y);
    const double dx = (s.sample(t, q.x + e, q.y).height - s.sample(t, q.x - e, q.y).height) / (2 * e);
    const double dz = (s.sample(t, q.x, q.y + e).height - s.sample(t, q.x, q.y - e).height) / (2 * e);
    EXPECT_LT(glm::distance(at.normal, glm::normalize(glm::dvec3(-dx, 1, -dz))), 1e-6);
    const glm::dvec3 v =
        (s.at_rest(at.rest_position, t + e).position - s.at_rest(at.rest_position, t - e).position) / (2 * e);
    EXPECT_LT(glm::distance(at.velocity, v), 1e-6);
  }
}

// Model gerstner with the scene's own waves: WaveQuery answers eq. 11 of the exact waves, each with its own
// steepness (written out here, not through the code under test), to rounding.
TEST(Gerstner, WaveQueryOfModelGerstnerAnswersEquationElevenOfTheExactWaves) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Gerstner;
  p.choppiness = 0.9;
  p.cascades = {{200, 128}, {20, 128}};
  p.gerstner.waves = {{0.6, 37, 20, 30, 0.95}, {0.2, 9.3, -40, 100, 0.2}, {0.03, 1.7, 75, 10}};
  ocean::WaveQuery query(p);
  constexpr double kRad = std::numbers::pi / 180;
  const GerstnerSurface cpu({.waves = {{0.6, 37, 20, 30 * kRad, 0.95},
                                       {0.2, 9.3, -40, 100 * kRad, 0.2},
                                       {0.03, 1.7, 75, 10 * kRad, 0.9}},
                             .limit_steepness = false});
  double worst = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = -50 + 2.71 * i, z = 13 - 1.93 * i, t = 0.37 * i;
    const ocean::WaveSample a = query.sample(t, x, z), b = cpu.sample(t, x, z);
    ASSERT_TRUE(b.converged);
    worst = std::max(worst, std::abs(a.height - b.height) + glm::distance(a.normal, b.normal));
  }
  RecordProperty("worst_error", std::to_string(worst));
  EXPECT_LT(worst, 1e-9);
}

// A 37 m wave is 37 m long (the cascades' lattice made it 37.14 m): one wave with Q = 0 repeats after exactly
// its wavelength along its direction and is opposite half a wavelength on.
TEST(Gerstner, AWaveKeepsItsExactWavelength) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Gerstner;
  p.choppiness = 0;
  p.gerstner.waves = {{0.6, 37, 20, 30}};
  ocean::WaveQuery query(p);
  const glm::dvec2 d(std::sin(20 * std::numbers::pi / 180), -std::cos(20 * std::numbers::pi / 180));
  double repeat = 0, opposite = 0;
  for (int i = 0; i < 20; ++i) {
    const glm::dvec2 x(-300 + 31.7 * i, 120 - 17.3 * i);
    const double t = 0.9 * i, h = query.sample(t, x.x, x.y).height;
    const glm::dvec2 far = x + 10 * 37.0 * d, half = x + 18.5 * d;
    repeat = std::max(repeat, std::abs(query.sample(t, far.x, far.y).height - h));
    opposite = std::max(opposite, std::abs(query.sample(t, half.x, half.y).height + h));
  }
  RecordProperty("repeat_error_m", std::to_string(repeat));
  EXPECT_LT(repeat, 1e-9);
  EXPECT_LT(opposite, 1e-9);
}

// Waves sampled from the spectrum go through the cascades on their lattice: WaveQuery (the FFT ocean's CPU
// query) answers eq. 11 of the lattice waves within its own error bound.
TEST(Gerstner, WaveQueryOfSampledGerstnerWavesAnswersTheLatticeWaves) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Gerstner;
  p.choppiness = 0.5;
  p.cascades = {{200, 128}, {20, 128}};
  p.gerstner.spectrum_waves = 24;
  ocean::WaveQuery query(p);
  const GerstnerSurface cpu(ocean::gerstner_params(p));
  double worst = 0, bound = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = -50 + 2.71 * i, z = 13 - 1.93 * i, t = 0.37 * i;
    const ocean::WaveSample a = query.sample(t, x, z), b = cpu.sample(t, x, z);
    ASSERT_TRUE(b.converged);
    worst = std::max(worst, std::abs(a.height - b.height));
    bound = a.error_bound_m;
  }
  RecordProperty("worst_height_error_m", std::to_string(worst));
  RecordProperty("bound_m", std::to_string(bound));
  EXPECT_LE(worst, bound);
  EXPECT_LT(worst, 0.01);
}

// Waves sampled from the spectrum (eq. 13's deterministic amplitudes): their variance Σ A²/2 is the
// spectrum's integral over the sampled band, PM written out here and integrated by Simpson (3 % allowed), and
// their energy-weighted direction is the wind's.
TEST(Gerstner, WavesSampledFromTheSpectrumCarryItsEnergy) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Gerstner;
  p.spectrum.type = ocean::SpectrumType::PiersonMoskowitz;
  p.spectrum.wind_speed_mps = 9;
  p.spectrum.wind_direction_deg = 40;
  p.gerstner.spectrum_waves = 32;
  const auto waves = ocean::gerstner_wave_specs(p);
  ASSERT_EQ(waves.size(), 32u);
  double variance = 0;
  glm::dvec2 heading(0.0);
  for (const auto& w : waves) {
    variance += 0.5 * w.amplitude_m * w.amplitude_m;
    const double a = w.direction_deg * std::numbers::pi / 180;
    heading += w.amplitude_m * w.amplitude_m * glm::dvec2(std::sin(a), std::cos(a));
  }
  const double wp = 2 * std::numbers::pi * 0.13 * kG / 9, lo = 0.6 * wp, hi = 4 * wp;
  const auto pm = [wp](double w) {
    return 0.0081 * kG * kG / std::pow(w, 5) * std::exp(-1.25 * std::pow(wp / w, 4));
  };
  double band = 0;
  const int n = 20000;
  for (int i = 0; i <= n; ++i) {
    const double w = lo + (hi - lo) * i / n;
    band += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * pm(w);
  }
  band *= (hi - lo) / n / 3;
  const double hs = 4 * std::sqrt(variance), hs_band = 4 * std::sqrt(band),
               hs_all = 4 * std::sqrt(0.0081 * kG * kG / (5 * std::pow(wp, 4)));
  RecordProperty("hs_sampled_m", std::to_string(hs));
  RecordProperty("hs_of_band_m", std::to_string(hs_band));
  RecordProperty("hs_of_spectrum_m", std::to_string(hs_all));  // PM: m0 = α g² / (5 ω_p⁴)
  EXPECT_NEAR(hs, hs_band, 0.03 * hs_band);
  EXPECT_NEAR(std::atan2(heading.x, heading.y) * 180 / std::numbers::pi, 40.0, 5.0);
  EXPECT_EQ(ocean::gerstner_wave_specs(p)[7].phase_deg, waves[7].phase_deg) << "deterministic";
}

}  // namespace
}  // namespace lagoon::test
