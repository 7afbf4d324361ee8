// The dynamic wave layer's CPU reference (compute/ocean/dynamic_layer.h, issue 14) against closed forms: a
// standing wave oscillates at Airy's ω = sqrt(g k tanh(k d)), a resting hull settles into its depression,
// the border absorbs a wave packet that runs into it, and a hull at constant speed in deep water draws
// Kelvin's wedge, its cusps at 19.47°.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "fft/cpu_fft.h"
#include "ocean/dynamic_layer.h"
#include "support/reference_math.h"

namespace lagoon::test {
namespace {

// Σ h² + (dh/dt / ω0)² over cells at least `margin` cells from the window's edges: twice the mean potential
// energy of a narrow-band wave of frequency ω0 (up to ρ g / 2 per cell area).
double interior_energy(const ocean::DynamicLayerCpu& layer, double omega0, int margin) {
  const int n = int(layer.params().n);
  const glm::ivec2 o = layer.window();
  double e = 0;
  for (int b = o.y + margin; b < o.y + n - margin; ++b)
    for (int a = o.x + margin; a < o.x + n - margin; ++a) {
      const double h = layer.height(a, b), v = layer.rate(a, b) / omega0;
      e += h * h + v * v;
    }
  return e;
}

TEST(DynamicLayer, AStandingWaveOscillatesAtAirysFrequency) {
  for (double depth : {0.0, 2.0}) {
    ocean::DynamicLayerParams p{
        .n = 64, .cell_m = 0.5, .depth_m = depth, .decay_per_s = 0, .sponge_per_s = 0};
    ocean::DynamicLayerCpu layer(p, 1);
    const double k = 2 * std::numbers::pi * 3 / (p.n * p.cell_m),
                 amplitude = 0.1;  // 3 wavelengths over the grid
    for (int b = 0; b < int(p.n); ++b)
      for (int a = 0; a < int(p.n); ++a)
        layer.state()[size_t(b) * p.n + a] = amplitude * std::cos(k * a * p.cell_m);
    const double omega = depth > 0 ? std::sqrt(kG * k * std::tanh(k * depth)) : std::sqrt(kG * k);
    double worst = 0;
    double t = 0;
    for (int s = 0; s < 40; ++s) {
      layer.step(0.137, {});
      t += 0.137;
      for (int a = 0; a < int(p.n); a += 5)
        worst = std::max(worst, std::abs(layer.height(a, 7) -
                                         amplitude * std::cos(k * a * p.cell_m) * std::cos(omega * t)));
    }
    EXPECT_LT(worst, 1e-9 * amplitude) << "depth " << depth;
  }
}

TEST(DynamicLayer, AHullAtRestSettlesIntoItsDepression) {
  ocean::DynamicLayerParams p{.n = 128, .cell_m = 0.25, .decay_per_s = 0.5, .sponge_m = 4};
  ocean::DynamicLayerCpu layer(p, 2);
  const ocean::WakeSource hull{.centre = {16, 16}, .sigma = {1.2, 0.5}, .depression = 0.3};
  for (int s = 0; s < 150; ++s) layer.step(0.1, {&hull, 1});  // 15 s: e^{-7.5} of the first response left
  // The Gaussian less its mean over the window (the mean level is not the layer's to move).
  const double mean = 0.3 * 2 * std::numbers::pi * 1.2 * 0.5 / ((p.n * p.cell_m) * (p.n * p.cell_m));
  EXPECT_NEAR(layer.height(64, 64), -0.3 + mean, 0.003);
  EXPECT_NEAR(layer.height(64 + 4, 64), -0.3 * std::exp(-0.5 * 1.0 / (0.5 * 0.5)) + mean,
              0.003);  // 1 m across
  EXPECT_NEAR(layer.height(64, 64 + 4), -0.3 * std::exp(-0.5 * 1.0 / (1.2 * 1.2)) + mean,
              0.003);  // 1 m along
}

// A packet of 4 m waves running toward +x, built in the Fourier domain from its positive wavenumbers only.
void launch_packet(ocean::DynamicLayerCpu& layer, double x0, double width, double wavelength) {
  const auto& p = layer.params();
  const int n = int(p.n);
  std::vector<std::complex<double>> h(size_t(n) * n);
  const double k0 = 2 * std::numbers::pi / wavelength;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double x = a * p.cell_m;
      h[size_t(b) * n + a] = 0.1 * std::exp(-0.5 * (x - x0) * (x - x0) / (width * width)) * std::cos(k0 * x);
    }
  fft::CpuFft2d(p.n, false).transform(h, 1);
  std::vector<std::complex<double>> z(h.size());
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const int f = a < n / 2 ? a : a - n;
      if (f <= 0 || b != 0) continue;  // the packet is uniform across: row 0 of the spectrum holds it all
      const double k = 2 * std::numbers::pi * f / (n * p.cell_m), omega = std::sqrt(kG * k);
      const std::complex<double> H = 2.0 * h[size_t(a)];  // both halves of the real wave, in one
      // h(x, t) = Re(H e^{i(kx - ωt)}): height H and rate -iωH, packed as h + i dh/dt before the transform.
      z[size_t(a)] = H / (double(n) * n);
      z[size_t(n - a)] = std::conj(H) / (double(n) * n);
      const std::complex<double> rate = std::complex<double>(0, -omega) * H / (double(n) * n);
      z[size_t(a)] += std::complex<double>(0, 1) * rate;
      z[size_t(n - a)] += std::complex<double>(0, 1) * std::conj(rate);
      z[size_t(a)] *= 0.5;
      z[size_t(n - a)] *= 0.5;
    }
  fft::CpuFft2d(p.n, true).transform(z, 1);
  layer.state() = z;
}

double absorbed_test_energy_ratio(double sponge_per_s) {
  ocean::DynamicLayerParams p{
      .n = 256, .cell_m = 0.25, .decay_per_s = 0, .sponge_m = 16, .sponge_per_s = sponge_per_s};
  ocean::DynamicLayerCpu layer(p, 2);
  launch_packet(layer, 26.0, 3.0, 4.0);
  const double omega0 = std::sqrt(kG * 2 * std::numbers::pi / 4.0);
  const int margin = int(p.sponge_m / p.cell_m);
  const double before = interior_energy(layer, omega0, margin);
  // Group velocity 1.25 m/s: the packet's front reaches the border at ~8 s, it has crossed the 16 m border
  // by ~35 s, and whatever the border reflected is back in the interior by 60 s.
  for (int s = 0; s < 600; ++s) layer.step(0.1, {});
  return interior_energy(layer, omega0, margin) / before;
}

TEST(DynamicLayer, TheBorderAbsorbsWhatLeavesTheWindow) {
  const double left = absorbed_test_energy_ratio(3.0);
  RecordProperty("energy_left", std::to_string(left));
  EXPECT_LT(left, 0.05);
  // Without the border's damping the packet comes round the periodic grid: the check can fail.
  EXPECT_GT(absorbed_test_energy_ratio(0.0), 0.5);
}

// The angle of the wake's cusps. At each distance behind the hull the envelope of |h| across the track
// (the largest |h| within a wavelength along it) has its outermost peak on the cusp line: beyond it the
// pattern dies away (Airy), inside it the transverse waves, highest on the track itself, take over. That peak
// is the outermost local maximum above 40 % of the row's largest. The lines through the peaks start a little
// behind the hull (its length), so the angle is their slope, fitted by least squares.
double cusp_angle_deg(const ocean::DynamicLayerCpu& layer, glm::dvec2 hull, double cell, double from_m,
                      double to_m) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (double behind = from_m; behind <= to_m; behind += 1.0) {
    const int a = int(std::lround((hull.x + behind) / cell));
    for (int side : {-1, 1}) {
      std::vector<double> envelope;
      for (double eta = 0; eta <= 0.7 * behind; eta += cell) {
        const int b = int(std::lround((hull.y + side * eta) / cell));
        double e = 0;
        for (int da = -4; da <= 4; ++da) e = std::max(e, std::abs(layer.height(a + da, b)));
        envelope.push_back(e);
      }
      const double top = *std::max_element(envelope.begin(), envelope.end());
      size_t peak = 0;
      for (size_t i = envelope.size() - 2; i > 0; --i)
        if (envelope[i] >= 0.4 * top && envelope[i] >= envelope[i - 1] && envelope[i] >= envelope[i + 1]) {
          peak = i;
          break;
        }
      const double eta = peak * cell;
      sx += behind, sy += eta, sxx += behind * behind, sxy += behind * eta;
      ++count;
    }
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  return std::atan(slope) * 180 / std::numbers::pi;
}

TEST(DynamicLayer, AHullAtConstantSpeedInDeepWaterDrawsKelvinsWedge) {
  ocean::DynamicLayerParams p{.n = 256, .cell_m = 0.5, .depth_m = 0, .decay_per_s = 0, .sponge_m = 12};
  ocean::DynamicLayerCpu layer(p, 2);
  // 3 m/s for a 2 x 1 m (sigma) footprint: a length Froude number of about 0.34, where the wake's highest
  // waves lie on the cusps (at higher speeds they move inward, Rabaud & Moisy 2013).
  ocean::WakeSource hull{.centre = {20, 64},
                         .velocity = {-3, 0},
                         .heading = -std::numbers::pi / 2,
                         .sigma = {2, 1},
                         .depression = 0.3};
  for (int s = 0; s < 500; ++s) {
    // The window follows the hull, 20 m from its front edge: the wake stays in it for ~95 m, and the waves
    // of the start leave through the back.
    layer.set_window({int(std::floor((hull.centre.x - 20) / p.cell_m)), 0});
    layer.step(0.1, {&hull, 1});
    hull.centre += hull.velocity * 0.1;
  }
  const double angle = cusp_angle_deg(layer, hull.centre, p.cell_m, 20, 80);
  RecordProperty("cusp_angle_deg", std::to_string(angle));
  EXPECT_NEAR(angle, 19.47, 2.0);
}

// Foam trails (the layer's foam, shaders/shared/dynamic_layer_math.h): a hull's trail fades as
// wakes.foam_lifetime_s says (to e^-3 over it), crossing trails saturate at 1, and a submerged vehicle (no
// foam rate) leaves none.
double total_foam(const ocean::DynamicLayerCpu& layer) {
  double sum = 0;
  for (double f : layer.foam()) sum += f;
  return sum;
}

TEST(DynamicLayerFoam, ATrailFadesAsItsLifetimeSays) {
  ocean::DynamicLayerParams p{.n = 128, .cell_m = 0.25, .sponge_m = 4, .foam_lifetime_s = 10};
  ocean::DynamicLayerCpu layer(p, 2);
  ocean::WakeSource hull{.centre = {6, 16},
                         .velocity = {4, 0},
                         .heading = std::numbers::pi / 2,
                         .sigma = {1.2, 0.5},
                         .depression = 0.2,
                         .foam_per_s = 8};
  for (int s = 0; s < 30; ++s) {  // 3 s: 12 m of trail, well inside the window
    layer.step(0.1, {&hull, 1});
    hull.centre += hull.velocity * 0.1;
  }
  const double laid = total_foam(layer);
  ASSERT_GT(laid, 100.0) << "no trail";
  double largest = 0;
  for (double f : layer.foam()) largest = std::max(largest, f);
  EXPECT_LE(largest, 1.0);
  EXPECT_GT(largest, 0.99) << "the stern's wash saturates the foam";
  // The hull leaves: the trail only fades.
  double t = 0;
  for (double age : {2.0, 5.0, 10.0}) {
    for (; t < age - 1e-9; t += 0.1) layer.step(0.1, {});
    const double expected = std::exp(-3.0 * age / p.foam_lifetime_s);
    EXPECT_NEAR(total_foam(layer) / laid, expected, 0.1 * expected) << "age " << age;
  }
}

// Seed 002 §3.3: the trail is the hull's width at its start and wider toward its end. The layer's foam
// diffuses sideways (wakes.foam_spread_m2_s): across a straight trail its variance grows by 2 D t, the
// closed form of diffusion (the decay scales every cell alike and leaves the shape).
double across_variance(const ocean::DynamicLayerCpu& layer, int n, double cell, double z_centre) {
  double sum = 0, moment = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double f = layer.foam(i, j), dz = j * cell - z_centre;
      sum += f;
      moment += f * dz * dz;
    }
  return moment / sum;
}

TEST(DynamicLayerFoam, ATrailWidensAsItAges) {
  for (const double spread : {0.1, 0.0}) {
    ocean::DynamicLayerParams p{
        .n = 128, .cell_m = 0.25, .sponge_m = 4, .foam_lifetime_s = 30, .foam_spread_m2_s = spread};
    ocean::DynamicLayerCpu layer(p, 2);
    ocean::WakeSource hull{.centre = {6, 16},
                           .velocity = {5, 0},
                           .heading = std::numbers::pi / 2,
                           .sigma = {1.2, 0.5},
                           .foam_per_s = 8};
    for (int s = 0; s < 36;
         ++s) {  // 18 m of trail along z = 16, inside the window's 24 m clear of its border
      layer.step(0.1, {&hull, 1});
      hull.centre += hull.velocity * 0.1;
    }
    for (int s = 0; s < 20; ++s) layer.step(0.1, {});  // the hull gone (out of the window's reach)
    const double early = across_variance(layer, 128, 0.25, 16);
    for (int s = 0; s < 60; ++s) layer.step(0.1, {});
    const double late = across_variance(layer, 128, 0.25, 16);
    RecordProperty("variance_growth_m2_at_" + std::to_string(spread), std::to_string(late - early));
    // Six seconds: 2 D t = 1.2 m² (the width's standard deviation from about 0.5 to 1.2 m).
    EXPECT_NEAR(late - early, 2 * spread * 6.0, 0.05 * 2 * 0.1 * 6.0) << "D = " << spread;
  }
}

TEST(DynamicLayerFoam, CrossingTrailsSaturateAndSubmergedHullsLeaveNone) {
  // A long lifetime: what the crossing holds is what the two trails laid there.
  ocean::DynamicLayerParams p{.n = 128, .cell_m = 0.25, .sponge_m = 4, .foam_lifetime_s = 3600};
  ocean::DynamicLayerCpu layer(p, 2);
  std::vector<ocean::WakeSource> hulls{{.centre = {6, 16},
                                        .velocity = {3, 0},
                                        .heading = std::numbers::pi / 2,
                                        .sigma = {1, 0.5},
                                        .foam_per_s = 40},
                                       {.centre = {16, 6},
                                        .velocity = {0, 3},
                                        .heading = std::numbers::pi,  // south, +z
                                        .sigma = {1, 0.5},
                                        .foam_per_s = 40},
                                       {.centre = {20, 26},
                                        .velocity = {-3, 0},
                                        .heading = -std::numbers::pi / 2,
                                        .sigma = {1, 0.2},
                                        .depth = 4}};
  for (int s = 0; s < 70; ++s) {
    layer.step(0.1, hulls);
    for (ocean::WakeSource& h : hulls) h.centre += h.velocity * 0.1;
  }
  double largest = 0;
  for (double f : layer.foam()) largest = std::max(largest, f);
  EXPECT_LE(largest, 1.0);
  EXPECT_GT(layer.foam(64, 64), 0.9) << "the crossing at (16, 16) is covered";
  // Where only the AUV passed (z = 26), no foam: only the far tail of the second trail, 4 m off and spreading
  // (2e-7; a trail the AUV laid would hold about 1).
  EXPECT_LT(layer.foam(int(12 / 0.25), int(26 / 0.25)), 1e-4);
}

}  // namespace
}  // namespace lagoon::test
