#include "validate_shore.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <memory>
#include <string>

#include "ocean/gerstner.h"
#include "ocean/initial_spectrum.h"
#include "ocean/shoaling.h"
#include "ocean/wave_query.h"

namespace lagoon::cli {
namespace {

// The beach: dry (-1 m) at z = 0, 20 m deep at z = 630 m (slope 1:30), flat beyond; the swell arrives from
// +z.
constexpr double kNear = -1, kFar = 20, kLength = 630;
double depth_at(double z) {
  return kNear + (kFar - kNear) * z / kLength;
}
double z_at(double depth) {
  return (depth - kNear) / (kFar - kNear) * kLength;
}

// Linear theory, computed here and not by ocean/shoaling.cpp: k from ω² = g k tanh(k h) by bisection.
double theory_k(double omega, double h) {
  double lo = omega * omega / kG * 0.999, hi = omega / std::sqrt(kG * h) * 1.001 + omega * omega / kG;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (lo + hi);
    (kG * m * std::tanh(m * h) < omega * omega ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

struct Swell {
  double period_s, angle_deg, amplitude_m;
  double omega() const { return 2 * kPi / period_s; }
  double k0() const { return omega() * omega() / kG; }
  double k_along() const { return k0() * std::sin(angle_deg * kPi / 180); }  // conserved
  double k_across(double h) const {
    const double k = theory_k(omega(), h);
    return std::sqrt(k * k - k_along() * k_along());
  }
  double theta_deg(double h) const { return std::asin(k_along() / theory_k(omega(), h)) * 180 / kPi; }
  // a0 K_s K_r: the energy flux E c_g cos θ conserved between rays.
  double amplitude(double h) const {
    const double k = theory_k(omega(), h);
    const double cg = 0.5 * (omega() / k) * (1 + 2 * k * h / std::sinh(2 * k * h));
    const double ks = std::sqrt(kG / (2 * omega()) / cg);
    const double kr = std::sqrt(std::cos(angle_deg * kPi / 180) / std::cos(theta_deg(h) * kPi / 180));
    return amplitude_m * ks * kr;
  }
};

std::shared_ptr<const ocean::DepthProfile> beach_floor(const ValidateOptions& o) {
  if (o.broken == "no-shoaling") return nullptr;
  auto floor = std::make_shared<ocean::DepthProfile>();
  floor->axis = {0, 1};
  const size_t n = size_t(kLength / 0.25) + 1;
  floor->spacing_m = kLength / double(n - 1);
  for (size_t i = 0; i < n; ++i) floor->depth_m.push_back(depth_at(floor->spacing_m * double(i)));
  return floor;
}

// A swell of the FFT ocean: one lattice mode k = 2π/L (mx, mz) of a cascade of L = 400 m (mz < 0: toward the
// beach), with its mirror, 0.1 m high in all.
struct LatticeMode {
  int mx, mz;
  static constexpr double kPatchM = 400;
  glm::dvec2 k() const { return 2 * kPi / kPatchM * glm::dvec2(mx, mz); }
  Swell swell() const {
    return {2 * kPi / std::sqrt(kG * glm::length(k())),
            std::atan2(std::abs(double(mx)), std::abs(double(mz))) * 180 / kPi, 0.1};
  }
};

class Beach {
 public:
  // A direct wave (ocean/gerstner.h).
  Beach(const Swell& s, const ValidateOptions& o) : swell_(s) {
    ocean::GerstnerParams p;
    p.limit_steepness = false;
    p.floor = beach_floor(o);
    p.waves.push_back({.amplitude_m = s.amplitude_m,
                       .wavelength_m = 2 * kPi / s.k0(),
                       .direction_deg = s.angle_deg,  // toward -z, the beach: north (core/compass.h)
                       .steepness = 0});
    auto surface = std::make_shared<ocean::GerstnerSurface>(std::move(p));
    height_ = [surface](double z, double t) { return surface->sample(t, 0.0, z).height; };
  }
  // The random sea's lattice (ocean/random_sea.h): a cascade holding one mode, without horizontal motion.
  Beach(const LatticeMode& m, const ValidateOptions& o) : swell_(m.swell()) {
    ocean::OceanParams p;
    p.cascades = {{LatticeMode::kPatchM, 64}};
    p.choppiness = 0;
    p.floor = beach_floor(o);
    ocean::CascadeSpectrum s = ocean::empty_cascade_spectrum(p, 0);
    const int n = int(s.resolution);
    const size_t cell = size_t((m.mz + n) % n) * size_t(n) + size_t((m.mx + n) % n),
                 mirrored = size_t((n - m.mz) % n) * size_t(n) + size_t((n - m.mx) % n);
    s.h0[cell] = {0.05f, 0.0f};
    s.omega[cell] = s.omega[mirrored] = float(swell_.omega());  // ω is even in k
    auto query = std::make_shared<ocean::WaveQuery>(p, std::vector<ocean::CascadeSpectrum>{s});
    height_ = [query](double z, double t) { return query->sample(t, 0.0, z).height; };
  }
  // The water's height above (0, z) at t, as WaveQuery answers it.
  double height(double z, double t = 0) const { return height_(z, t); }
  // The two up-crossings across the shore whose midpoint is nearest z0: one wavelength.
  std::pair<double, double> wavelength_around(double z0, double guess_m) const {
    std::pair<double, double> best{0, HUGE_VAL};
    const double dz = guess_m / 1000;
    double prev = height(z0 - 2.5 * guess_m), last_up = NAN;
    for (double z = z0 - 2.5 * guess_m + dz; z <= z0 + 2.5 * guess_m; z += dz) {
      const double h = height(z);
      if (prev < 0 && h >= 0) {
        const double up = z - dz * h / (h - prev);
        if (!std::isnan(last_up) &&
            std::abs(0.5 * (last_up + up) - z0) < std::abs(0.5 * (best.first + best.second) - z0))
          best = {last_up, up};
        last_up = up;
      }
      prev = h;
    }
    return best;
  }
  // Half the range of the height at (0, z) over a period.
  double amplitude(double z) const {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int i = 0; i < 128; ++i) {
      const double h = height(z, swell_.period_s * i / 128.0);
      lo = std::min(lo, h), hi = std::max(hi, h);
    }
    return 0.5 * (hi - lo);
  }

 private:
  Swell swell_;
  std::function<double(double, double)> height_;
};

// Theory's k across the shore averaged over [z1, z2]: what one wavelength between crossings spans.
double mean_k_across(const Swell& s, double z1, double z2) {
  double sum = 0;
  constexpr int kSteps = 100;
  for (int i = 0; i < kSteps; ++i) sum += s.k_across(depth_at(z1 + (i + 0.5) * (z2 - z1) / kSteps));
  return sum / kSteps;
}

}  // namespace

std::vector<Law> shore_laws(const ValidateOptions& o) {
  if (!o.wants("shore")) return {};
  const std::string on =
      "cpu: WaveQuery's sums over the floor's table (ocean/gerstner.h, ocean/shoaling.h), "
      "which the renderer draws in float";
  const std::string beach =
      "A planar beach along z (1:30, 20 m deep to 1 m of dry land) and a monochromatic swell of period T "
      "arriving at angle a from the beach's normal, heights 0.4 to 0.8 m (T s / a deg: ";
  Law wavelength{.id = "shore.wavelength",
                 .title = "Local wavelength from omega^2 = g k tanh(k h)",
                 .source = "Airy 1845; linear wave theory (Dean & Dalrymple 1991, ch. 3)",
                 .measured_on = on,
                 .x_label = "depth h (m)",
                 .y_label = "wavelength across the shore (m)",
                 .tolerance = "±5 %"};
  Law snell{.id = "shore.snell",
            .title = "Refraction: sin(theta) / c constant (Snell's law)",
            .source = "Snell's law over straight, parallel depth contours (Dean & Dalrymple 1991, ch. 4)",
            .measured_on = on,
            .x_label = "depth h (m)",
            .y_label = "wave direction from the beach's normal (deg)",
            .tolerance = "±2°"};
  Law amplitude{
      .id = "shore.shoaling",
      .title = "Shoaling and refraction: a = a0 Ks Kr",
      .source = "Green's law generalised: energy flux E cg cos(theta) conserved (Dean & Dalrymple 1991)",
      .measured_on = on,
      .x_label = "depth h (m)",
      .y_label = "amplitude (m)",
      .tolerance = "±10 %"};
  Law breaking{.id = "shore.breaking-onset",
               .title = "Depth-limited breaking at H / h = 0.78",
               .source = "McCowan 1894 (the solitary wave's limit)",
               .measured_on = on,
               .x_label = "wave period T (s)",
               .y_label = "H / h where the height first falls below linear theory",
               .tolerance = "±0.1"};
  const std::vector<Swell> swells =
      o.quick ? std::vector<Swell>{{10, 20, 0.3}, {14, 40, 0.25}}
              : std::vector<Swell>{{6, 0, 0.2}, {8, 30, 0.4}, {10, 20, 0.3}, {12, 10, 0.35}, {14, 40, 0.25}};
  const std::vector<double> depths =
      o.quick ? std::vector<double>{12, 4} : std::vector<double>{15, 10, 6, 4, 2.5};
  std::string list;
  for (const Swell& s : swells)
    list +=
        (list.empty() ? "" : ", ") + std::to_string(int(s.period_s)) + "/" + std::to_string(int(s.angle_deg));
  wavelength.note = beach + list +
                    "). Crossings: the spacing of the up-crossings around each depth, against theory's "
                    "wavenumber averaged over that wavelength.";
  snell.note = beach + list +
               "). The direction from the measured wavelength across the shore and the (conserved) one along "
               "it, against Snell's law at the depth midway.";
  amplitude.note = beach + list +
                   "). Half the height's range over a period; depths where linear theory's height exceeds "
                   "0.78 h are the next law's.";
  breaking.note = beach + list +
                  "). From 10 m toward the shore in 2 cm steps, the first depth where the height falls 1 % "
                  "below linear theory's; its linear height over that depth.";
  Law lattice_wavelength = wavelength, lattice_snell = snell, lattice_amplitude = amplitude;
  lattice_wavelength.id = "shore.lattice-wavelength";
  lattice_wavelength.title = "The FFT ocean's local wavelength from omega^2 = g k tanh(k h)";
  lattice_snell.id = "shore.lattice-snell";
  lattice_snell.title = "The FFT ocean's refraction: Snell's law";
  lattice_amplitude.id = "shore.lattice-shoaling";
  lattice_amplitude.title = "The FFT ocean's shoaling and refraction: a = a0 Ks Kr";
  lattice_wavelength.measured_on = lattice_snell.measured_on = lattice_amplitude.measured_on =
      "cpu: WaveQuery's cascades read at their lattice's move over the floor (ocean/random_sea.h, "
      "shared/shoaling_math.h), which the renderer draws in float";
  const std::vector<LatticeMode> modes = o.quick
                                             ? std::vector<LatticeMode>{{2, -4}}
                                             : std::vector<LatticeMode>{{0, -3}, {1, -5}, {2, -4}, {3, -3}};
  std::string mode_list;
  for (const LatticeMode& m : modes)
    mode_list += (mode_list.empty() ? "" : ", ") + std::to_string(m.mx) + "/" + std::to_string(m.mz);
  const std::string lattice_beach =
      "The same beach under the random sea: a 400 m cascade of 64² holding one mode (mx/mz: " + mode_list +
      "; 7.0-9.2 s, 0-45 deg) and its mirror, 0.1 m high, no choppiness. ";
  lattice_wavelength.note = lattice_beach + "Its up-crossings as above.";
  lattice_snell.note = lattice_beach + "Its direction as above.";
  lattice_amplitude.note =
      lattice_beach + "Half its height's range over a period, far below its depth limit.";
  size_t done = 0;
  for (const LatticeMode& m : modes) {
    const Swell s = m.swell();
    const Beach b(m, o);
    for (double h : depths) {
      const auto [z1, z2] = b.wavelength_around(z_at(h), 2 * kPi / s.k_across(h));
      const double expected = 2 * kPi / mean_k_across(s, z1, z2);
      lattice_wavelength.points.push_back(relative_point(h, expected, (z2 - z1) * o.scale(), 0.05));
      const double measured_deg = std::atan2(s.k_along(), 2 * kPi / (z2 - z1)) * 180 / kPi;
      lattice_snell.points.push_back(
          absolute_point(h, s.theta_deg(depth_at(0.5 * (z1 + z2))), measured_deg * o.scale(), 2.0));
      lattice_amplitude.points.push_back(
          relative_point(h, s.amplitude(h), b.amplitude(z_at(h)) * o.scale(), 0.10));
    }
  }
  for (const Swell& s : swells) {
    const Beach b(s, o);
    for (double h : depths) {
      const double guess = 2 * kPi / s.k_across(h);
      const auto [z1, z2] = b.wavelength_around(z_at(h), guess);
      const double expected = 2 * kPi / mean_k_across(s, z1, z2);
      wavelength.points.push_back(relative_point(h, expected, (z2 - z1) * o.scale(), 0.05));
      const double measured_deg = std::atan2(s.k_along(), 2 * kPi / (z2 - z1)) * 180 / kPi;
      snell.points.push_back(
          absolute_point(h, s.theta_deg(depth_at(0.5 * (z1 + z2))), measured_deg * o.scale(), 2.0));
      if (2 * s.amplitude(h) <= 0.78 * h)
        amplitude.points.push_back(relative_point(h, s.amplitude(h), b.amplitude(z_at(h)) * o.scale(), 0.10));
    }
    double ratio = 0;
    for (double h = 10; h > 0.05 && ratio == 0; h -= 0.02)
      if (b.amplitude(z_at(h)) < 0.99 * s.amplitude(h)) ratio = 2 * s.amplitude(h) / h;
    breaking.points.push_back(absolute_point(s.period_s, 0.78, ratio * o.scale(), 0.1));
    validate_progress("shore", ++done, swells.size());
  }
  return {wavelength, snell, amplitude, breaking, lattice_wavelength, lattice_snell, lattice_amplitude};
}

}  // namespace lagoon::cli
