#include "validate_sea.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "core/compass.h"
#include "ocean/dispersion.h"
#include "ocean/field_statistics.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/height_probe.h"
#include "ocean/initial_spectrum.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectrum.h"
#include "validate_foam.h"

namespace lagoon::cli {
namespace {

// ---- The published laws, written here from their papers (not from Lagoon's spectrum code). ----

// Pierson & Moskowitz (1964): ω_p = 0.8772 g/U19.5 ≈ 2π·0.13 g/U10, S = α g² ω⁻⁵ exp(-5/4 (ω_p/ω)⁴),
// α = 0.0081, so m0 = α g² / (5 ω_p⁴).
double pm_peak_omega(double u10) {
  return 2.0 * kPi * 0.13 * kG / u10;
}
double pm_hs(double u10) {
  return 4.0 * std::sqrt(0.0081 * kG * kG / (5.0 * std::pow(pm_peak_omega(u10), 4)));
}

// Hasselmann et al. (1973), JONSWAP: α = 0.076 χ^-0.22, ω_p = 22 (g/U) χ^-1/3, χ = gF/U², γ = 3.3, σ =
// 0.07/0.09; m0 by quadrature of the spectrum (Simpson in ln ω).
double jonswap_density(double w, double alpha, double wp, double gamma) {
  const double sigma = w <= wp ? 0.07 : 0.09, r = std::exp(-std::pow((w - wp) / (sigma * wp), 2) / 2);
  return alpha * kG * kG * std::pow(w, -5) * std::exp(-1.25 * std::pow(wp / w, 4)) * std::pow(gamma, r);
}
double integrate_ln(const std::function<double(double)>& f, double a, double b, int n = 4000) {
  const double u0 = std::log(a), h = (std::log(b) - u0) / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = std::exp(u0 + i * h);
    sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * f(x) * x;
  }
  return sum * h / 3;
}
double jonswap_law_peak(double u10, double fetch_m) {
  return 22.0 * kG / u10 * std::pow(kG * fetch_m / (u10 * u10), -1.0 / 3);
}
double jonswap_law_hs(double u10, double fetch_m) {
  const double alpha = 0.076 * std::pow(kG * fetch_m / (u10 * u10), -0.22),
               wp = jonswap_law_peak(u10, fetch_m);
  return 4.0 * std::sqrt(integrate_ln([&](double w) { return jonswap_density(w, alpha, wp, 3.3); }, 0.05 * wp,
                                      50 * wp));
}

// Kitaigorodskii, Krasitskii & Zaslavskii (1975), exactly: the finite-depth spectrum is the deep one times
// Φ = k(ω,h)⁻³ dk/dω / (k∞⁻³ dk∞/dω), k from ω² = g k tanh(kh) (Bouws et al. 1985, TMA).
double depth_factor(double w, double h) {
  auto k_of = [h](double om) {
    double k = om * om / kG;
    for (int i = 0; i < 60; ++i) k = om * om / (kG * std::tanh(k * h));  // fixed point, converges for om > 0
    return k;
  };
  const double dw = 1e-5 * w, k = k_of(w), dk = (k_of(w + dw) - k_of(w - dw)) / (2 * dw);
  const double kinf = w * w / kG, dkinf = 2 * w / kG;
  return (dk / (k * k * k)) / (dkinf / (kinf * kinf * kinf));
}

// Cox & Munk (1954), clean surface: σ_u² = 3.16e-3 U, σ_c² = 0.003 + 1.92e-3 U (U at 12.5 m, m/s).
double cox_munk_upwind(double u) {
  return 3.16e-3 * u;
}
double cox_munk_crosswind(double u) {
  return 0.003 + 1.92e-3 * u;
}

// ---- Lagoon's seas, measured. ----

// A deep sea of JONSWAP type for a wind and fetch, with cascades sized to its peak wavelength so the
// longest waves fit: 20, 2 and 0.2 peak wavelengths.
ocean::OceanParams sea(double u10, double fetch_km, const ValidateOptions& o) {
  ocean::OceanParams p;
  p.spectrum.type = ocean::SpectrumType::Jonswap;
  p.spectrum.wind_speed_mps = u10;
  p.spectrum.fetch_km = fetch_km;
  p.spectrum.swell = 0.0;
  p.spectrum.cap_at_full_development = o.broken != "uncapped-fetch";
  p.depth_m = 4000.0;
  const double wp = ocean::peak_omega(p.spectrum), lp = 2 * kPi * kG / (wp * wp);
  const uint32_t n = o.quick ? 128 : 256;
  p.cascades = {{20 * lp, n}, {2 * lp, n}, {0.2 * lp, n}};
  return p;
}

struct SeaMeasurement {
  double hs = 0, peak_omega = 0;
};

// The GPU's height fields at `time_s`: Hs = 4σ, and the peak of the modes' energy density over frequency
// (2 %-wide bins, smoothed over ±6 %: robust against one lucky mode).
SeaMeasurement measure(vk::Context& ctx, const ocean::OceanParams& p, double time_s) {
  ocean::GpuOcean gpu(ctx, p);
  ctx.submit_and_wait([&](VkCommandBuffer cmd) { gpu.record_step(cmd, time_s, 0.0); });
  std::vector<ocean::HeightGrid> grids;
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) {
    const ocean::CascadeReadback r = gpu.read_cascade(c);
    ocean::HeightGrid g{.n = r.resolution, .patch_m = p.cascades[c].patch_size_m};
    g.height.resize(size_t{r.resolution} * r.resolution);
    for (size_t i = 0; i < g.height.size(); ++i) g.height[i] = r.displacement[4 * i + 1];
    grids.push_back(std::move(g));
  }
  const ocean::DispersionModel dispersion{p.depth_m, true, 0.0};
  const double w_lo = 0.2 * ocean::peak_omega(p.spectrum), bin = std::log(1.02);
  std::vector<double> energy(400, 0.0);
  for (const ocean::HeightGrid& g : grids) {
    const ocean::ModeEnergy e = ocean::mode_energy(g);
    for (uint32_t iz = 0; iz < e.n; ++iz)
      for (uint32_t ix = 0; ix < e.n; ++ix) {
        const double w = ocean::omega(dispersion, glm::length(e.wavevector(ix, iz)));
        const long b = w > w_lo ? long(std::log(w / w_lo) / bin) : -1;
        if (b >= 0 && b < long(energy.size())) energy[size_t(b)] += e.energy[size_t{iz} * e.n + ix];
      }
  }
  // The peak of the binned density smoothed over ±3 bins, refined by a parabola through its neighbours.
  std::vector<double> smooth(energy.size(), 0.0);
  for (size_t b = 3; b + 3 < energy.size(); ++b)
    for (int d = -3; d <= 3; ++d) {
      const size_t j = size_t(long(b) + d);
      smooth[b] += (4.0 - std::abs(d)) * energy[j] / (w_lo * std::exp((double(j) + 0.5) * bin) * bin);
    }
  const size_t top = size_t(std::max_element(smooth.begin(), smooth.end()) - smooth.begin());
  double offset = 0;
  if (top > 0 && top + 1 < smooth.size()) {
    const double a = smooth[top - 1], b = smooth[top], c = smooth[top + 1], curve = a - 2 * b + c;
    if (curve < 0) offset = std::clamp(0.5 * (a - c) / curve, -0.5, 0.5);
  }
  const double peak = w_lo * std::exp((double(top) + 0.5 + offset) * bin);
  return {ocean::significant_height(grids), peak};
}

// Seas of several seeds, averaged: one realisation's Hs and peak scatter by a few %.
SeaMeasurement measure_averaged(vk::Context& ctx, ocean::OceanParams p, const ValidateOptions& o) {
  SeaMeasurement sum;
  const int seeds = o.quick ? 2 : 4;
  for (int i = 0; i < seeds; ++i) {
    p.seed = uint32_t(11 + i);
    const SeaMeasurement m = measure(ctx, p, 100.0);
    sum.hs += m.hs / seeds, sum.peak_omega += m.peak_omega / seeds;
  }
  sum.hs *= o.scale(), sum.peak_omega /= o.scale();
  return sum;
}

std::vector<double> winds(const ValidateOptions& o) {
  return o.quick ? std::vector<double>{6, 12, 20} : std::vector<double>{6, 8, 10, 12, 14, 16, 18, 20};
}

// Pierson–Moskowitz at full development: a fetch of 5000 km, far beyond it at every wind.
std::vector<Law> full_development(vk::Context& ctx, const ValidateOptions& o) {
  Law hs{.id = "sea-state.pm-hs",
         .title = "Hs at full development",
         .source = "Pierson & Moskowitz 1964",
         .measured_on = "device: the cascades' heights read back",
         .x_label = "U10 (m/s)",
         .y_label = "Hs (m)",
         .tolerance = "±10 %",
         .note =
             "JONSWAP scene spectrum, fetch 5000 km, swell 0, depth 4000 m, cascades of 20, 2 and 0.2 peak "
             "wavelengths. Reference Hs = 4 sqrt(α g²/(5 ω_p⁴)), α = 0.0081, ω_p = 2π·0.13 g/U10."};
  Law tp = hs;
  tp.id = "sea-state.pm-tp", tp.title = "Peak period at full development", tp.y_label = "Tp (s)";
  tp.note =
      "As above; Lagoon's peak from the read-back modes' spectrum (Young 1995's E⁴-weighted "
      "frequency). Reference Tp = 2π/ω_p = U10 / (0.13 g).";
  const std::vector<double> us = winds(o);
  for (size_t i = 0; i < us.size(); ++i) {
    const SeaMeasurement m = measure_averaged(ctx, sea(us[i], 5000.0, o), o);
    hs.points.push_back(relative_point(us[i], pm_hs(us[i]), m.hs, 0.10));
    tp.points.push_back(relative_point(us[i], 2 * kPi / pm_peak_omega(us[i]), 2 * kPi / m.peak_omega, 0.10));
    validate_progress("full development", i + 1, us.size());
  }
  return {hs, tp};
}

// JONSWAP's fetch laws below full development (χ = gF/U² from 100 to 1900, where γ is still the scene's).
std::vector<Law> fetch_limited(vk::Context& ctx, const ValidateOptions& o) {
  Law hs{.id = "sea-state.jonswap-hs",
         .title = "Hs against fetch (fetch-limited)",
         .source = "Hasselmann et al. 1973 (JONSWAP)",
         .measured_on = "device: the cascades' heights read back",
         .x_label = "dimensionless fetch gF/U2",
         .y_label = "Hs (m) at 10 m/s",
         .tolerance = "±10 %",
         .log_x = true,
         .log_y = true,
         .note =
             "U10 = 10 m/s, swell 0. Reference: 4 sqrt(m0) of the JONSWAP spectrum with α = 0.076 χ^-0.22, "
             "ω_p = 22 (g/U) χ^-1/3, γ = 3.3, integrated here by quadrature."};
  Law tp = hs;
  tp.id = "sea-state.jonswap-tp", tp.title = "Peak period against fetch (fetch-limited)";
  tp.y_label = "Tp (s) at 10 m/s";
  tp.note = "As above; reference Tp = 2π/ω_p.";
  const std::vector<double> chis =
      o.quick ? std::vector<double>{150, 1500} : std::vector<double>{100, 200, 400, 800, 1500};
  const double u = 10.0;
  for (size_t i = 0; i < chis.size(); ++i) {
    const double fetch_m = chis[i] * u * u / kG;
    const SeaMeasurement m = measure_averaged(ctx, sea(u, fetch_m / 1000.0, o), o);
    hs.points.push_back(relative_point(chis[i], jonswap_law_hs(u, fetch_m), m.hs, 0.10));
    tp.points.push_back(
        relative_point(chis[i], 2 * kPi / jonswap_law_peak(u, fetch_m), 2 * kPi / m.peak_omega, 0.10));
    validate_progress("fetch-limited seas", i + 1, chis.size());
  }
  return {hs, tp};
}

// A longer fetch never raises the sea above Pierson–Moskowitz's, and Hs never falls as the fetch grows:
// the scene spectrum's Hs (from Lagoon's own S(ω), the one the cascades sample) over 1 km - 10 000 km.
Law fetch_cap(const ValidateOptions& o) {
  Law law{.id = "sea-state.fetch-cap",
          .title = "No sea beyond full development",
          .source = "Pierson & Moskowitz 1964; Hasselmann et al. 1973",
          .measured_on = "cpu: the scene spectrum S(w) the cascades sample, by quadrature",
          .x_label = "fetch (km)",
          .y_label = "Hs / Hs_PM at 6 m/s",
          .tolerance = "≤ 1.05, never falling",
          .log_x = true,
          .note =
              "U10 = 6 m/s, where the fetch laws alone gave 4.6 m (5.1x PM) at 1000 km. Each point's bound "
              "is also the previous point's value (Hs must not fall as the fetch grows)."};
  const double u = 6.0, pm = pm_hs(u);
  double last = 0;
  for (double f = 1.0; f <= 1.0e4 * 1.0001; f *= o.quick ? 3.0 : 1.6) {
    ocean::SpectrumParams s;
    s.wind_speed_mps = u, s.fetch_km = f, s.cap_at_full_development = o.broken != "uncapped-fetch";
    const double hs = 4 *
                      std::sqrt(integrate_ln(
                          [&](double w) { return ocean::frequency_spectrum(s, 4000.0, w); }, 0.05, 60.0)) *
                      o.scale();
    LawPoint p = at_most_point(f, 1.0, hs / pm, 0.05);
    p.low = last * (1.0 - 1e-9);  // monotone
    law.points.push_back(p);
    last = hs / pm;
  }
  return law;
}

// TMA (Bouws et al. 1985): in depth h the spectrum is JONSWAP's times Kitaigorodskii's Φ(ω, h).
Law tma_depth(vk::Context& ctx, const ValidateOptions& o) {
  Law law{
      .id = "sea-state.tma-depth",
      .title = "Depth-limited Hs (TMA)",
      .source = "Bouws et al. 1985; Kitaigorodskii et al. 1975",
      .measured_on = "device: the cascades' heights read back",
      .x_label = "depth h (m)",
      .y_label = "Hs (m)",
      .tolerance = "±10 %",
      .log_x = true,
      .note =
          "Spectrum type tma, U10 = 12 m/s, fetch 20 km (fetch-limited). Reference: 4 sqrt(∫ S_J(ω) Φ(ω,h) "
          "dω), S_J JONSWAP's fetch laws as above, Φ the exact ratio k⁻³dk/dω over its deep-water value, "
          "integrated here."};
  const double u = 12.0, fetch_m = 20e3;
  const std::vector<double> depths =
      o.quick ? std::vector<double>{2, 8} : std::vector<double>{1.5, 3, 6, 12, 25};
  const double alpha = 0.076 * std::pow(kG * fetch_m / (u * u), -0.22), wp = jonswap_law_peak(u, fetch_m);
  for (size_t i = 0; i < depths.size(); ++i) {
    const double h = depths[i];
    ocean::OceanParams p = sea(u, fetch_m / 1000.0, o);
    p.depth_m = h;
    p.spectrum.type = o.broken == "deep-tma" ? ocean::SpectrumType::Jonswap : ocean::SpectrumType::Tma;
    // Shallow waves are shorter than deep ones: the same patches hold them.
    const double reference =
        4 * std::sqrt(integrate_ln(
                [&](double w) { return jonswap_density(w, alpha, wp, 3.3) * depth_factor(w, h); }, 0.05 * wp,
                50 * wp));
    law.points.push_back(relative_point(h, reference, measure_averaged(ctx, p, o).hs, 0.10));
    validate_progress("depth-limited seas", i + 1, depths.size());
  }
  return law;
}

// Zero-up-crossing wave heights of time series at fixed points, against Rayleigh's exceedance
// P(H > x H_rms) = exp(-x²) (Longuet-Higgins 1952). The points stand 2.5 peak wavelengths apart, where the
// sea's heights are uncorrelated, and each series is 75 peak periods long: more independent waves for the
// same cost than a few long series at nearby points. The tolerance is the sampling error's: Kolmogorov and
// Smirnov's 1 % critical distance between an empirical distribution of n independent values and the true
// one, 1.63/√n, so the verdict is a test at the 1 % level rather than the luck of one sample. Successive
// waves in a group are not independent (their heights correlate by 0.4-0.6 in JONSWAP seas: Rye 1974,
// Battjes & van Vledder 1984), so the N waves count as n = N/2.
Law rayleigh(const ValidateOptions& o) {
  const int points = o.quick ? 4 : 16;
  Law law{.id = "sea-state.rayleigh",
          .title = "Wave heights are Rayleigh-distributed",
          .source = "Longuet-Higgins 1952; Kolmogorov-Smirnov 1 % band",
          .measured_on = "cpu: the band-limited sum the GPU draws, at fixed points (ocean/height_probe.h)",
          .x_label = "H / H_rms",
          .y_label = "P(wave height > H)",
          .tolerance = "±1.63/√(N/2)",
          .note = "U10 = 10 m/s, fully developed, zero-up-crossing heights of the time series at " +
                  std::to_string(points) +
                  " points 2.5 peak wavelengths apart, each 75 peak periods long, sampled at Tp/25; the band "
                  "is the Kolmogorov-Smirnov 1 % critical distance for N/2 independent waves (successive "
                  "heights in a group correlate)."};
  ocean::OceanParams p = sea(10.0, 5000.0, o);
  const std::vector<ocean::CascadeSpectrum> spectra = ocean::make_cascade_spectra(p);
  const ocean::HeightProbe probe(p, spectra, 0.005);
  const double wp = ocean::peak_omega(p.spectrum), tp = 2 * kPi / wp, dt = tp / 25;
  const double spacing = 2.5 * 2 * kPi * kG / (wp * wp);  // 2.5 peak wavelengths (deep water)
  // The broken variant: a regular wave at the peak, every height the same.
  const bool regular = o.broken == "regular-sea";
  auto height = [&](double t, double x, double z) {
    return regular ? std::cos(wp * t - wp * wp / kG * x) : probe.height(t, x, z).height;
  };
  std::vector<double> heights;
  for (int point = 0; point < points; ++point) {
    const double x = spacing * (point % 4), z = spacing * (point / 4);
    double last = 0, lo = 0, hi = 0;
    bool started = false;
    for (double t = 0; t < 75 * tp; t += dt) {
      const double h = height(t, x, z);
      if (last < 0 && h >= 0) {
        if (started) heights.push_back(hi - lo);
        started = true, lo = hi = h;
      }
      lo = std::min(lo, h), hi = std::max(hi, h), last = h;
    }
  }
  double square = 0;
  for (double h : heights) square += h * h;
  const double waves = double(std::max<size_t>(heights.size(), 1));
  // Fewer than 100 waves test nothing: the band is then 0, and the law fails.
  const double rms = std::sqrt(square / waves) * o.scale(),
               band = heights.size() >= 100 ? 1.63 / std::sqrt(waves / 2) : 0.0;
  for (double x = 0.25; x <= 2.0 + 1e-9; x += 0.25) {
    const double over =
        double(std::count_if(heights.begin(), heights.end(), [&](double h) { return h > x * rms; }));
    law.points.push_back(absolute_point(x, std::exp(-x * x), over / waves, band));
  }
  char n[96];
  std::snprintf(n, sizeof n, " %zu waves: band ±%.3f.", heights.size(), band);
  law.note += n;
  return law;
}

// Mean square slope along and across the wind: every cascade's plus the unresolved waves the glint counts.
std::vector<Law> cox_munk(const ValidateOptions& o) {
  Law up{
      .id = "slopes.cox-munk-upwind",
      .title = "Upwind mean square slope",
      .source = "Cox & Munk 1954 (clean surface)",
      .measured_on =
          "cpu: the cascades' sampled amplitudes plus the spectrum to 1 cm (ocean/slope_statistics.h)",
      .x_label = "U (m/s)",
      .y_label = "mean square slope",
      .tolerance = "±20 %",
      .note =
          "Scene spectrum at full development (fetch 5000 km), the default cascades of 1000, 100 and 10 m, "
          "beyond them Elfouhaily et al. (1997)'s capillary-gravity waves (ocean/short_waves.h). Reference "
          "σ_u² = 3.16e-3 U. From 4 m/s: below it the crosswind fit is mostly its constant 0.003, slopes "
          "the local wind does not make (at 3 m/s Lagoon has 0.75 of it, at 2 m/s 0.62)."};
  Law cross = up;
  cross.id = "slopes.cox-munk-crosswind", cross.title = "Crosswind mean square slope";
  cross.note = "As above; reference σ_c² = 0.003 + 1.92e-3 U.";
  for (double u : o.quick ? std::vector<double>{4, 10} : std::vector<double>{4, 5, 6, 8, 10, 12, 14}) {
    ocean::OceanParams p;
    p.spectrum.wind_speed_mps = u, p.spectrum.fetch_km = 5000.0, p.spectrum.swell = 0.0;
    const ocean::SlopeMoments m = o.broken == "resolved-slopes"
                                      ? [&] {
                                          ocean::SlopeMoments sum;
                                          for (const auto& s : ocean::make_cascade_spectra(p)) {
                                            const ocean::SlopeMoments c = ocean::slope_moments(s);
                                            sum.xx += c.xx, sum.zz += c.zz, sum.xz += c.xz;
                                          }
                                          return sum;
                                        }()
                                      : ocean::sea_slope_moments(p);
    const glm::dvec2 wind = compass::toward_deg(p.spectrum.wind_direction_deg);
    const double wx = wind.x, wz = wind.y;
    const double along = m.xx * wx * wx + 2 * m.xz * wx * wz + m.zz * wz * wz;
    const double across = m.xx * wz * wz - 2 * m.xz * wx * wz + m.zz * wx * wx;
    up.points.push_back(relative_point(u, cox_munk_upwind(u), along * o.scale(), 0.20));
    cross.points.push_back(relative_point(u, cox_munk_crosswind(u), across * o.scale(), 0.20));
  }
  return {up, cross};
}

// Monahan & O'Muircheartaigh (1980): whitecap coverage W = 3.84e-6 U10^3.41 (a fraction).
double monahan(double u10) {
  return 3.84e-6 * std::pow(u10, 3.41);
}

// The share of the sea's area where the foam Lagoon draws is at least 0.5 (drawn_foam, validate_foam.h) on
// a 512² grid over the largest patch, averaged over 10 frames 1 s apart after 30 s of steps at 10 Hz (15 s
// in --quick: foam lasts 4.2 s at most at the default decay of 0.3/s). One frame is not enough: the
// whitecaps are mostly the finest cascade's, a few dozen patches on its tile at light winds.
double foam_coverage(vk::Context& ctx, const ocean::OceanParams& p, const ValidateOptions& o) {
  ocean::GpuOcean gpu(ctx, p);
  const double dt = 0.1;
  const int warm = o.quick ? 150 : 300, frames = 10, apart = 10;
  const uint32_t grid = 512;
  size_t foamy = 0;
  int step = 0;
  for (int frame = 0; frame < frames; ++frame) {
    const int until = warm + frame * apart;
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      for (; step < until; ++step)
        gpu.record_step(cmd, 100.0 + step * dt, step == 0 ? 0.0 : dt, nullptr,
                        step + 1 < until ? ocean::GpuOcean::Step::WarmUp : ocean::GpuOcean::Step::Full);
    });
    const std::vector<uint8_t> drawn = drawn_foam(gpu, p, grid, p.cascades[0].patch_size_m);
    foamy += size_t(std::count(drawn.begin(), drawn.end(), uint8_t{1}));
  }
  return double(foamy) / (double(frames) * grid * grid);
}

Law whitecaps(vk::Context& ctx, const ValidateOptions& o) {
  Law law{
      .id = "foam.whitecap-coverage",
      .title = "Whitecap coverage",
      .source = "Monahan & O'Muircheartaigh 1980",
      .measured_on =
          "device: the foam and Jacobian fields read back at 10 frames 1 s apart after 30 s of "
          "steps (15 s in --quick)",
      .x_label = "U10 (m/s)",
      .y_label = "whitecap coverage (fraction of the area)",
      .tolerance = "factor 2",
      .log_y = true,
      .note =
          "Coverage: the share of the area where the foam Lagoon draws (each cascade's, and the whole "
          "sea's Jacobian's, as the surface shader combines them) is at least 0.5, averaged over 10 "
          "frames 1 s apart. Fully developed "
          "JONSWAP sea, the default foam settings (coverage monahan, decay 0.3/s), cascades of 20, 2 and 0.2 "
          "peak wavelengths. Reference W = 3.84e-6 U10^3.41."};
  const std::vector<double> us = winds(o);
  for (size_t i = 0; i < us.size(); ++i) {
    ocean::OceanParams p = sea(us[i], 5000.0, o);
    if (o.broken == "seed-foam") p.foam.coverage = ocean::FoamCoverage::Threshold;
    const double w = foam_coverage(ctx, p, o) * o.scale();
    law.points.push_back(factor_point(us[i], monahan(us[i]), std::max(w, 1e-6), 2.0));
    validate_progress("whitecaps", i + 1, us.size());
  }
  return law;
}

}  // namespace

std::vector<Law> sea_state_laws(vk::Context& ctx, const ValidateOptions& o) {
  std::vector<Law> laws;
  auto add = [&](std::vector<Law> more) {
    for (Law& law : more) laws.push_back(std::move(law));
  };
  if (o.wants("sea-state.pm")) add(full_development(ctx, o));
  if (o.wants("sea-state.jonswap")) add(fetch_limited(ctx, o));
  if (o.wants("sea-state.fetch-cap")) add({fetch_cap(o)});
  if (o.wants("sea-state.tma-depth")) add({tma_depth(ctx, o)});
  if (o.wants("sea-state.rayleigh")) add({rayleigh(o)});
  if (o.wants("slopes")) add(cox_munk(o));
  if (o.wants("foam")) add({whitecaps(ctx, o)});
  return laws;
}

}  // namespace lagoon::cli
