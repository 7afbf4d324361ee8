// Waves over the floor (ocean/shoaling.h, issue 37) against linear wave theory on a planar beach: a
// monochromatic swell of several periods and angles, evaluated by GerstnerSurface as every user of the sea
// sees it, measured the way one would measure a wave tank (zero crossings, heights over a period), and
// compared with the theory computed here independently (the dispersion relation by bisection, c_g in closed
// form, Snell's law, energy flux): local wavelength within 5 %, amplitude within 10 % of K_s K_r up to the
// breaking zone, direction within 2 degrees, breaking onset at H/h = 0.78 ± 0.1, and a sea over a floor
// deeper than half its longest wavelength unchanged to the bit.
#include "ocean/shoaling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>
#include <vector>

#include "core/compass.h"
#include "ocean/direct_waves.h"
#include "ocean/gerstner.h"
#include "ocean/random_sea.h"
#include "ocean/wave_query.h"
#include "scene/floor_profile.h"
#include "support/gltf_quads.h"
#include "support/temp_dir.h"

namespace lagoon::test {
namespace {

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

// A planar beach along +z: dry (-1 m) at z = 0, 20 m deep at z = 630 m (slope 1:30), flat beyond.
std::shared_ptr<const ocean::DepthProfile> planar_beach(double near_m = -1, double far_m = 20,
                                                        double length_m = 630) {
  auto p = std::make_shared<ocean::DepthProfile>();
  p->axis = {0, 1};
  const size_t n = size_t(length_m / 0.25) + 1;
  p->spacing_m = length_m / double(n - 1);
  for (size_t i = 0; i < n; ++i) p->depth_m.push_back(near_m + (far_m - near_m) * double(i) / double(n - 1));
  return p;
}
// The same beach, 1:30 on to 100 m deep (z = 3030 m), sampled on a grid of `spacing_m` whose axes are
// turned `turn_deg` from the world's, so its contours cross the grid's lines: as a glTF floor is sampled
// (scene/floor_profile.h) and solved in two dimensions (the eikonal and the energy flux) from the deep water
// where the waves are their own.
std::shared_ptr<const ocean::DepthProfile> grid_beach(double turn_deg, double spacing_m) {
  auto p = std::make_shared<ocean::DepthProfile>();
  const double a = turn_deg * kPi / 180;
  p->axis = {std::cos(a), std::sin(a)};
  const glm::dvec2 centre(0, 1500), u = p->axis, v = p->across();
  const double half = 1800;  // the turned square covers x in ±600 m, z from -150 to 3150 m
  p->origin = centre - half * u - half * v;
  p->spacing_m = spacing_m;
  const size_t n = size_t(2 * half / spacing_m) + 1;
  p->rows = n;
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec2 x = p->origin + spacing_m * (double(i) * u + double(j) * v);
      p->depth_m.push_back(std::clamp(-1 + 21 * x.y / 630, -1.0, 100.0));
    }
  return p;
}

double beach_z(double depth_m) {
  return (depth_m + 1) / 21.0 * 630;
}

// Linear theory, independently of ocean/shoaling.cpp: k from ω² = g k tanh(k h) by bisection, c_g = n c.
double theory_k(double omega, double h) {
  double lo = omega * omega / kG * 0.999, hi = omega / std::sqrt(kG * h) * 1.001 + omega * omega / kG;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (lo + hi);
    (kG * m * std::tanh(m * h) < omega * omega ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}
double theory_cg(double omega, double h) {
  const double k = theory_k(omega, h);
  return 0.5 * (omega / k) * (1 + 2 * k * h / std::sinh(2 * k * h));
}

struct Swell {
  double period_s, angle_deg, amplitude_m;
  double omega() const { return 2 * kPi / period_s; }
  double k0() const { return omega() * omega() / kG; }
  double k_along_shore() const { return k0() * std::sin(angle_deg * kPi / 180); }
  // Snell's law and energy flux: direction from the beach's normal, and K_s K_r a0.
  double theta_deg(double h) const { return std::asin(k_along_shore() / theory_k(omega(), h)) * 180 / kPi; }
  double amplitude(double h) const {
    const double ks = std::sqrt(kG / (2 * omega()) / theory_cg(omega(), h));
    const double kr = std::sqrt(std::cos(angle_deg * kPi / 180) / std::cos(theta_deg(h) * kPi / 180));
    return amplitude_m * ks * kr;
  }
};

ocean::GerstnerSurface beach_surface(const Swell& s, double breaker = ocean::kBreakerIndex,
                                     std::shared_ptr<const ocean::DepthProfile> floor = planar_beach()) {
  ocean::GerstnerParams p;
  p.limit_steepness = false;
  p.floor = std::move(floor);
  p.breaker_index = breaker;
  // Toward the beach (-z: north, core/compass.h), angle_deg off its normal.
  p.waves.push_back({.amplitude_m = s.amplitude_m,
                     .wavelength_m = 2 * kPi / s.k0(),
                     .direction_deg = s.angle_deg,
                     .steepness = 0});
  return ocean::GerstnerSurface(std::move(p));
}

double height(const ocean::GerstnerSurface& surface, double x, double z, double t = 0) {
  return surface.at_rest({x, z}, t).position.y;
}

// The two up-crossings of h(x = 0, z) whose midpoint is nearest z0: one local wavelength across the shore.
struct Crossings {
  double z1 = 0, z2 = HUGE_VAL;
  double spacing() const { return z2 - z1; }
};
Crossings crossings_around(const ocean::GerstnerSurface& surface, double z0, double window) {
  std::vector<double> up;
  const double dz = window / 4000;
  double prev = height(surface, 0, z0 - window);
  for (double z = z0 - window + dz; z <= z0 + window; z += dz) {
    const double h = height(surface, 0, z);
    if (prev < 0 && h >= 0) up.push_back(z - dz * h / (h - prev));
    prev = h;
  }
  Crossings best;
  for (size_t i = 0; i + 1 < up.size(); ++i)
    if (std::abs(0.5 * (up[i] + up[i + 1]) - z0) < std::abs(0.5 * (best.z1 + best.z2) - z0))
      best = {up[i], up[i + 1]};
  return best;
}

// Theory's k across the shore, averaged over [z1, z2]: what one wavelength's crossings span (2π / spacing).
double theory_mean_kz(const Swell& s, Crossings c) {
  double sum = 0;
  constexpr int kSteps = 200;
  for (int i = 0; i < kSteps; ++i) {
    const double z = c.z1 + (i + 0.5) * c.spacing() / kSteps, h = z / 630 * 21 - 1;
    const double k = theory_k(s.omega(), h);
    sum += std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
  }
  return sum / kSteps;
}

// Half the crest-to-trough range of h(0, z, t) over a period.
double measured_amplitude(const ocean::GerstnerSurface& surface, const Swell& s, double z) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i < 256; ++i) {
    const double h = height(surface, 0, z, s.period_s * i / 256.0);
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  return 0.5 * (hi - lo);
}

const Swell kSwells[] = {{6, 0, 0.2}, {10, 20, 0.3}, {14, 40, 0.25}, {8, 30, 0.4}};
const double kDepths[] = {15, 8, 4, 2.5};

TEST(Shoaling, LocalWavelengthFollowsTheFiniteDepthDispersionRelation) {
  for (const Swell& s : kSwells) {
    const ocean::GerstnerSurface surface = beach_surface(s);
    for (double h : kDepths) {
      const double k = theory_k(s.omega(), h);
      const double kz = std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
      const Crossings c = crossings_around(surface, beach_z(h), 2.5 * 2 * kPi / kz);
      const double expected = 2 * kPi / theory_mean_kz(s, c);
      EXPECT_NEAR(c.spacing(), expected, 0.05 * expected) << "T " << s.period_s << " s, h " << h << " m";
    }
  }
}

TEST(Shoaling, WavesTurnTowardTheShallowsBySnellsLaw) {
  for (const Swell& s : kSwells) {
    const ocean::GerstnerSurface surface = beach_surface(s);
    for (double h : kDepths) {
      const double k = theory_k(s.omega(), h);
      const double kz = std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
      // Crests along the shore repeat every 2π/k_x (conserved), across it every measured 2π/k_z: the wave's
      // direction over the wavelength measured, against Snell's law at the depth midway.
      const Crossings c = crossings_around(surface, beach_z(h), 2.5 * 2 * kPi / kz);
      const double measured = std::atan2(s.k_along_shore(), 2 * kPi / c.spacing()) * 180 / kPi;
      const double h_mid = 0.5 * (c.z1 + c.z2) / 630 * 21 - 1;
      EXPECT_NEAR(measured, s.theta_deg(h_mid), 2.0) << "T " << s.period_s << " s, h " << h << " m";
    }
  }
}

TEST(Shoaling, AmplitudeIsShoalingTimesRefractionUpToTheBreakingZone) {
  for (const Swell& s : kSwells) {
    const ocean::GerstnerSurface surface = beach_surface(s);
    for (double h : kDepths) {
      const double expected = s.amplitude(h);
      if (2 * expected > 0.78 * h) continue;  // breaking: the next test's
      EXPECT_NEAR(measured_amplitude(surface, s, beach_z(h)), expected, 0.1 * expected)
          << "T " << s.period_s << " s, angle " << s.angle_deg << ", h " << h << " m";
    }
  }
}

// From deep water toward the shore, the first depth where the measured height falls below linear theory's.
double breaking_onset_ratio(const ocean::GerstnerSurface& surface, const Swell& s) {
  for (double h = 10; h > 0.05; h -= 0.02) {
    const double linear = s.amplitude(h);
    if (measured_amplitude(surface, s, beach_z(h)) < 0.99 * linear) return 2 * linear / h;
  }
  return 0;
}

TEST(Shoaling, WavesBreakWhereTheirHeightReachesTheBreakerIndex) {
  for (const Swell& s : kSwells)
    EXPECT_NEAR(breaking_onset_ratio(beach_surface(s), s), 0.78, 0.1) << "T " << s.period_s << " s";
  // Past the onset the height stays at γ h, and the wave ends at the shoreline.
  const Swell s = kSwells[1];
  const ocean::GerstnerSurface surface = beach_surface(s);
  EXPECT_NEAR(2 * measured_amplitude(surface, s, beach_z(0.5)), 0.78 * 0.5, 0.03);
  EXPECT_EQ(measured_amplitude(surface, s, beach_z(-0.2)), 0.0);
}

TEST(Shoaling, ASeaOverAFloorDeeperThanHalfItsLongestWaveIsUnchangedToTheBit) {
  const Swell s{10, 20, 0.3};  // 156 m long: half is 78 m
  const ocean::GerstnerSurface over_floor =
      beach_surface(s, ocean::kBreakerIndex, planar_beach(80, 200, 400));
  EXPECT_EQ(over_floor.shoaling(), nullptr);
  ocean::GerstnerParams open = over_floor.params();
  open.floor = nullptr;
  const ocean::GerstnerSurface open_sea(open);
  for (double z : {-50.0, 10.0, 200.0, 900.0})
    for (double t : {0.0, 3.7}) {
      const ocean::WaveSample a = over_floor.sample(t, 12.5, z), b = open_sea.sample(t, 12.5, z);
      EXPECT_EQ(a.height, b.height);
      EXPECT_EQ(a.normal, b.normal);
      EXPECT_EQ(a.velocity, b.velocity);
    }
  // Just shallower than that, the floor matters.
  EXPECT_NE(beach_surface(s, ocean::kBreakerIndex, planar_beach(70, 200, 400)).shoaling(), nullptr);
}

// A floor sampled on a grid (a glTF floor's path) is solved in two dimensions, to first order: the same laws
// hold with the same tolerances, on a grid turned 25° from the beach's contours, 4 m apart.
TEST(Shoaling, OnAGridTheSameLawsHold) {
  const auto grid = grid_beach(25, 4.0);
  for (const Swell& s : {Swell{8, 30, 0.4}, Swell{10, 20, 0.3}}) {  // both find their own depth on the grid
    const ocean::GerstnerSurface surface = beach_surface(s, ocean::kBreakerIndex, grid);
    ASSERT_NE(surface.shoaling(), nullptr);
    double worst_length = 0, worst_angle = 0, worst_amplitude = 0;
    for (double h : kDepths) {
      const double k = theory_k(s.omega(), h);
      const double kz = std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
      const Crossings c = crossings_around(surface, beach_z(h), 2.5 * 2 * kPi / kz);
      const double expected = 2 * kPi / theory_mean_kz(s, c);
      worst_length = std::max(worst_length, std::abs(c.spacing() / expected - 1));
      EXPECT_NEAR(c.spacing(), expected, 0.05 * expected) << "T " << s.period_s << " s, h " << h << " m";
      const double angle = std::atan2(s.k_along_shore(), 2 * kPi / c.spacing()) * 180 / kPi;
      const double h_mid = 0.5 * (c.z1 + c.z2) / 630 * 21 - 1;
      worst_angle = std::max(worst_angle, std::abs(angle - s.theta_deg(h_mid)));
      EXPECT_NEAR(angle, s.theta_deg(h_mid), 2.0) << "T " << s.period_s << " s, h " << h << " m";
      if (2 * s.amplitude(h) > 0.78 * h) continue;
      const double a = measured_amplitude(surface, s, beach_z(h));
      worst_amplitude = std::max(worst_amplitude, std::abs(a / s.amplitude(h) - 1));
      EXPECT_NEAR(a, s.amplitude(h), 0.1 * s.amplitude(h)) << "T " << s.period_s << " s, h " << h << " m";
    }
    EXPECT_NEAR(breaking_onset_ratio(surface, s), 0.78, 0.1) << "T " << s.period_s << " s";
    std::printf("grid, T %.0f s at %.0f deg: wavelength %.2f %%, direction %.2f deg, amplitude %.2f %%\n",
                s.period_s, s.angle_deg, 100 * worst_length, worst_angle, 100 * worst_amplitude);
  }
}

// A glTF floor (scene/floor_profile.h): the same beach as a 1200 m square tilted 1:30 (dry at z = 0, 39 m
// deep at z = 1200), rasterised onto its grid, with the open sea beyond it: the depths are the plane's, and a
// 6 s swell (its own beyond 28 m) obeys the same laws over it as over the slope floor.
TEST(Shoaling, AGltfFloorIsSampledAndTheWavesFeelIt) {
  TempDir dir;
  const double alpha = std::atan(1.0 / 30), theta = kPi / 2 + alpha;  // the quad's y axis down the slope
  write_quads(dir / "beach.gltf", {{.material = nlohmann::json::object(),
                                    .translation = {0, 1 - 600.0 / 30, 600},
                                    .rotation = {std::sin(theta / 2), 0, 0, std::cos(theta / 2)},
                                    .half = float(600 / std::cos(alpha))}});
  scene::Seafloor floor;
  floor.type = scene::SeafloorType::Gltf;
  floor.file = (dir / "beach.gltf").string();
  const auto grid = scene::floor_profile(floor, 1000);
  ASSERT_NE(grid, nullptr);
  EXPECT_GT(grid->rows, 200u);
  for (double z : {30.0, 300.0, 900.0})
    EXPECT_NEAR(grid->depth_at(grid->local({17, z})), -1 + z / 30, 1e-3) << z;
  EXPECT_EQ(grid->depth_at(grid->local({0, 1300})), 1000);  // beyond the mesh: the open sea

  const Swell s{6, 20, 0.2};
  const ocean::GerstnerSurface surface = beach_surface(s, ocean::kBreakerIndex, grid);
  ASSERT_NE(surface.shoaling(), nullptr);
  for (double h : {15.0, 8.0, 4.0}) {
    const double k = theory_k(s.omega(), h);
    const double kz = std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
    const Crossings c = crossings_around(surface, beach_z(h), 2.5 * 2 * kPi / kz);
    const double expected = 2 * kPi / theory_mean_kz(s, c);
    EXPECT_NEAR(c.spacing(), expected, 0.05 * expected) << "h " << h << " m";
    EXPECT_NEAR(measured_amplitude(surface, s, beach_z(h)), s.amplitude(h), 0.1 * s.amplitude(h))
        << "h " << h;
  }
}

// Swell trains over the random sea (ocean.swell_waves): WaveQuery answers the cascades' sea plus the swell's
// sum at the same rest point, with its slopes added; a swell without steepness moves no water sideways, so
// the rest point is the sea's own.
TEST(Shoaling, SwellOverTheRandomSeaIsAddedToIt) {
  ocean::OceanParams sea;
  sea.cascades = {{200.0, 64}, {20.0, 64}};
  ocean::OceanParams with_swell = sea;
  with_swell.swell_waves = {{.amplitude_m = 0.4, .wavelength_m = 90, .direction_deg = 30, .steepness = 0.0}};
  ocean::WaveQuery alone(sea), both(with_swell);
  const ocean::GerstnerSurface swell(*ocean::swell_wave_params(with_swell, {}));
  for (const glm::dvec2 q : {glm::dvec2(3, 4), glm::dvec2(-40, 17.5), glm::dvec2(120, -60)}) {
    const ocean::WaveSample a = alone.sample(2.5, q.x, q.y), b = both.sample(2.5, q.x, q.y);
    const ocean::GerstnerPoint s = swell.at_rest(a.rest_position, 2.5);
    EXPECT_NEAR(b.height, a.height + s.position.y, 1e-9);
    EXPECT_NEAR(glm::length(b.rest_position - a.rest_position), 0.0, 1e-9);
    const glm::dvec2 slope =
        -glm::dvec2(a.normal.x, a.normal.z) / a.normal.y - glm::dvec2(s.normal.x, s.normal.z) / s.normal.y;
    EXPECT_NEAR(glm::length(-glm::dvec2(b.normal.x, b.normal.z) / b.normal.y - slope), 0.0, 1e-9);
    EXPECT_GT(std::abs(s.position.y), 0.0);
  }
  // The models with their own waves ignore it.
  with_swell.model = ocean::SurfaceModel::Gerstner;
  EXPECT_FALSE(ocean::swell_wave_params(with_swell, {}).has_value());
}

TEST(Shoaling, TheWaveNumberSolvesTheDispersionRelation) {
  for (double omega : {0.3, 1.0, 3.0})
    for (double h : {0.1, 2.0, 30.0, 500.0}) {
      const double k = ocean::Shoaling::wavenumber(omega, h);
      EXPECT_NEAR(kG * k * std::tanh(k * h), omega * omega, 1e-9 * omega * omega);
      EXPECT_NEAR(ocean::Shoaling::group_velocity(omega, h), theory_cg(omega, h), 1e-9);
    }
}

// The random sea's lattice over the floor (ocean/random_sea.h): a cascade holding one mode, a swell of the
// FFT ocean, travels toward the planar beach. Its cascade is read where its lattice has moved
// (shared/shoaling_math.h), so the mode shortens, turns and grows as linear theory says, measured from
// WaveQuery's heights as the direct waves are (zero crossings, the range over a period): local wavelength
// within 5 %, direction within 2°, amplitude within 10 % of a0 K_s K_r (far below its depth limit here).
struct LatticeSwell {
  int mx, mz;  // the mode: k = 2π/L (mx, mz), L = 400 m; mz < 0 travels toward the beach (-z)
  double patch_m = 400;
  glm::dvec2 k() const { return 2 * kPi / patch_m * glm::dvec2(mx, mz); }
  Swell swell() const {
    const double omega = std::sqrt(kG * glm::length(k()));
    // h0(k) and its mirror each add 0.05 m: 0.1 m in all.
    return {2 * kPi / omega, std::atan2(std::abs(double(mx)), std::abs(double(mz))) * 180 / kPi, 0.1};
  }
};

ocean::OceanParams lattice_sea_params(std::shared_ptr<const ocean::DepthProfile> floor) {
  ocean::OceanParams p;
  p.cascades = {{400.0, 64}};
  p.choppiness = 0;  // no horizontal motion: the rest point is the point asked, as for the zero crossings
  p.floor = std::move(floor);
  return p;
}

std::vector<ocean::CascadeSpectrum> one_mode(const ocean::OceanParams& p, const LatticeSwell& m) {
  ocean::CascadeSpectrum s = ocean::empty_cascade_spectrum(p, 0);
  const int n = int(s.resolution);
  const size_t cell = size_t((m.mz + n) % n) * size_t(n) + size_t((m.mx + n) % n),
               mirrored = size_t((n - m.mz) % n) * size_t(n) + size_t((n - m.mx) % n);
  s.h0[cell] = {0.05f, 0.0f};
  // ω is even in k: the mirrored cell carries conj(h0(k)) (ocean/spectral_fields.h).
  s.omega[cell] = s.omega[mirrored] =
      float(std::sqrt(kG * glm::length(m.k()) * std::tanh(glm::length(m.k()) * p.depth_m)));
  return {s};
}

Crossings lattice_crossings(ocean::WaveQuery& q, double z0, double window) {
  std::vector<double> up;
  const double dz = window / 4000;
  std::vector<glm::dvec2> points;
  for (double z = z0 - window; z <= z0 + window; z += dz) points.push_back({0, z});
  const std::vector<ocean::WaveSample> s = q.sample(0.0, points);
  for (size_t i = 1; i < s.size(); ++i)
    if (s[i - 1].height < 0 && s[i].height >= 0)
      up.push_back(points[i].y - dz * s[i].height / (s[i].height - s[i - 1].height));
  Crossings best;
  for (size_t i = 0; i + 1 < up.size(); ++i)
    if (std::abs(0.5 * (up[i] + up[i + 1]) - z0) < std::abs(0.5 * (best.z1 + best.z2) - z0))
      best = {up[i], up[i + 1]};
  return best;
}

TEST(Shoaling, TheRandomSeasLatticeShortensTurnsAndGrowsAsLinearTheorySays) {
  for (const LatticeSwell& m : {LatticeSwell{0, -3}, LatticeSwell{2, -4}, LatticeSwell{1, -5}}) {
    const Swell s = m.swell();
    const ocean::OceanParams p = lattice_sea_params(planar_beach());
    ocean::WaveQuery q(p, one_mode(p, m));
    double worst_length = 0, worst_angle = 0, worst_amplitude = 0;
    for (double h : kDepths) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (int i = 0; i < 64; ++i) {
        const double height = q.sample(s.period_s * i / 64.0, 0.0, beach_z(h)).height;
        lo = std::min(lo, height);
        hi = std::max(hi, height);
      }
      worst_amplitude = std::max(worst_amplitude, std::abs(0.5 * (hi - lo) / s.amplitude(h) - 1));
      EXPECT_NEAR(0.5 * (hi - lo), s.amplitude(h), 0.1 * s.amplitude(h))
          << "mode " << m.mx << ", " << m.mz << ", h " << h;
      const double k = theory_k(s.omega(), h);
      const double kz = std::sqrt(k * k - s.k_along_shore() * s.k_along_shore());
      const Crossings c = lattice_crossings(q, beach_z(h), 2.5 * 2 * kPi / kz);
      const double expected = 2 * kPi / theory_mean_kz(s, c);
      worst_length = std::max(worst_length, std::abs(c.spacing() / expected - 1));
      EXPECT_NEAR(c.spacing(), expected, 0.05 * expected) << "mode " << m.mx << ", " << m.mz << ", h " << h;
      const double angle = std::atan2(s.k_along_shore(), 2 * kPi / c.spacing()) * 180 / kPi;
      const double h_mid = 0.5 * (c.z1 + c.z2) / 630 * 21 - 1;
      worst_angle = std::max(worst_angle, std::abs(angle - s.theta_deg(h_mid)));
      EXPECT_NEAR(angle, s.theta_deg(h_mid), 2.0) << "mode " << m.mx << ", " << m.mz << ", h " << h;
    }
    std::printf("lattice, T %.1f s at %.1f deg: wavelength %.2f %%, direction %.2f deg, amplitude %.2f %%\n",
                s.period_s, s.angle_deg, 100 * worst_length, worst_angle, 100 * worst_amplitude);
  }
}

// The slope WaveQuery answers over the floor is its height's own slope (the chain rule through the move):
// against central differences of its heights, within 3 % of a k (the cascade's Catmull-Rom interpolation
// of its slope against the slope of its interpolated height: 1-2 %); left out, it would be k0/k of it.
TEST(Shoaling, TheMovedLatticesSlopeIsItsHeightsSlope) {
  const LatticeSwell m{2, -4};
  const ocean::OceanParams p = lattice_sea_params(planar_beach());
  ocean::WaveQuery q(p, one_mode(p, m));
  double worst = 0;
  for (double h : {12.0, 4.0, 1.5})
    for (double dx : {0.0, 3.0, 7.5}) {
      const glm::dvec2 at(dx, beach_z(h));
      constexpr double kStep = 0.01;
      const std::vector<glm::dvec2> points = {at, at + glm::dvec2(kStep, 0), at - glm::dvec2(kStep, 0),
                                              at + glm::dvec2(0, kStep), at - glm::dvec2(0, kStep)};
      const std::vector<ocean::WaveSample> s = q.sample(1.3, points);
      const glm::dvec2 numeric((s[1].height - s[2].height) / (2 * kStep),
                               (s[3].height - s[4].height) / (2 * kStep));
      const glm::dvec2 answered = -glm::dvec2(s[0].normal.x, s[0].normal.z) / s[0].normal.y;
      // a k, the slope's size: h0(k) and its mirror each add 0.05 m to the amplitude.
      const double scale = 0.1 * theory_k(m.swell().omega(), h);
      worst = std::max(worst, glm::length(answered - numeric) / scale);
      EXPECT_NEAR(glm::length(answered - numeric), 0.0, 0.03 * scale) << "h " << h << ", x " << dx;
    }
  std::printf("lattice slope against its heights' differences: worst %.3f %% of a k\n", 100 * worst);
}

// A cascade's representative wave: its modes' variance-weighted wavenumber and direction.
TEST(Shoaling, ACascadesRepresentativeWaveIsItsModesWeightedByTheirVariance) {
  ocean::OceanParams p = lattice_sea_params(nullptr);
  p.depth_m = 30;
  ocean::CascadeSpectrum s = ocean::empty_cascade_spectrum(p, 0);
  const double dk = 2 * kPi / 400;
  s.h0[size_t(64 - 3) * 64 + 0] = {1.0f, 0.0f};  // k = dk (0, -3), variance 1
  s.h0[size_t(4) * 64 + 4] = {0.0f, 2.0f};       // k = dk (4, 4), variance 4
  const ocean::ShoalingWave w = ocean::representative_wave(s, p);
  const double k = (1 * 3 * dk + 4 * std::sqrt(32.0) * dk) / 5;
  const glm::dvec2 toward = glm::normalize(1.0 * glm::dvec2(0, -1) + 4.0 * glm::dvec2(1, 1) / std::sqrt(2.0));
  EXPECT_NEAR(glm::length(w.k), k, 1e-9 * k);
  EXPECT_NEAR(glm::dot(glm::normalize(w.k), toward), 1.0, 1e-12);
  EXPECT_NEAR(w.omega, std::sqrt(kG * k * std::tanh(k * 30)), 1e-9);
  EXPECT_EQ(w.own_depth_m, 30);
  EXPECT_EQ(glm::length(ocean::representative_wave(ocean::empty_cascade_spectrum(p, 0), p).k), 0.0);
}

// Deeper than half the representative wave's length everywhere, the lattice is not moved and the sea is the
// deep sea's to the bit; just shallower, it is moved.
TEST(Shoaling, ARandomSeaOverADeepFloorIsUnchangedToTheBit) {
  const LatticeSwell m{0, -3};  // 133 m long: half is 67 m
  const ocean::OceanParams deep = lattice_sea_params(planar_beach(70, 200, 400));
  ocean::OceanParams open = deep;
  open.floor = nullptr;
  ocean::WaveQuery over(deep, one_mode(deep, m)), alone(open, one_mode(open, m));
  for (double z : {-50.0, 10.0, 200.0})
    for (double t : {0.0, 3.7}) {
      const ocean::WaveSample a = over.sample(t, 12.5, z), b = alone.sample(t, 12.5, z);
      EXPECT_EQ(a.height, b.height);
      EXPECT_EQ(a.normal, b.normal);
    }
  EXPECT_EQ(ocean::sea_over_floor(deep, ocean::random_sea(deep, one_mode(deep, m))), nullptr);
  const ocean::OceanParams shallower = lattice_sea_params(planar_beach(60, 200, 400));
  EXPECT_NE(ocean::sea_over_floor(shallower, ocean::random_sea(shallower, one_mode(shallower, m))), nullptr);
}

}  // namespace
}  // namespace lagoon::test
