#include "validate_foam.h"

#include <algorithm>
#include <cmath>

#include "ocean/foam_law.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/spectrum.h"
#include "ocean/whitecaps.h"

namespace lagoon::cli {
namespace {

// A fully developed JONSWAP sea at u10 with the wind toward north (-z), cascades of 20, 2 and 0.2 peak
// wavelengths.
ocean::OceanParams foam_sea(double u10, uint32_t n) {
  ocean::OceanParams p;
  p.spectrum.type = ocean::SpectrumType::Jonswap;
  p.spectrum.wind_speed_mps = u10;
  p.spectrum.fetch_km = 5000.0;
  p.spectrum.swell = 0.0;
  p.spectrum.wind_direction_deg = 0.0;
  p.depth_m = 4000.0;
  const double wp = ocean::peak_omega(p.spectrum), lp = 2 * kPi * kG / (wp * wp);
  p.cascades = {{20 * lp, n}, {2 * lp, n}, {0.2 * lp, n}};
  return p;
}

// Where a correlation, sampled at lags 0, step, 2 step..., first falls to 1/e (linear between samples).
double e_folding(const std::vector<double>& r, double step) {
  for (size_t k = 1; k < r.size(); ++k)
    if (r[k] <= std::exp(-1.0)) {
      const double f = (r[k - 1] - std::exp(-1.0)) / (r[k - 1] - r[k]);
      return (double(k - 1) + f) * step;
    }
  return double(r.size()) * step;
}

struct FoamStats {
  double lifetime_s = 0;             // e-folding of the foam's autocorrelation in time at fixed points
  double along_m = 0, across_m = 0;  // e-folding lengths of its autocorrelation along and across the wind
};

FoamStats measure_foam(vk::Context& ctx, double u10, const ValidateOptions& o) {
  ocean::OceanParams p = foam_sea(u10, o.quick ? 128 : 256);
  // Foam that fades within a step: whitecaps that last only while the surface folds.
  if (o.broken == "fleeting-foam") p.foam.decay_per_s = 30;
  ocean::GpuOcean gpu(ctx, p);
  const double dt = 0.1;
  const int warm = 150, frames = 100;
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    for (int i = 0; i < warm; ++i)
      gpu.record_step(cmd, 100.0 + i * dt, i == 0 ? 0.0 : dt, nullptr, ocean::GpuOcean::Step::WarmUp);
  });
  const uint32_t grid = 256;
  const double side = 3 * p.cascades[2].patch_size_m;
  std::vector<std::vector<uint8_t>> series;
  for (int f = 0; f < frames; ++f) {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) { gpu.record_step(cmd, 100.0 + (warm + f) * dt, dt); });
    series.push_back(drawn_foam(gpu, p, grid, side));
  }
  FoamStats s;
  double on = 0;
  for (const auto& frame : series)
    for (uint8_t v : frame) on += v;
  const double share = on / (double(frames) * grid * grid);
  const double var = share - share * share;
  // In time.
  std::vector<double> rt;
  for (int lag = 0; lag < 60; ++lag) {
    double both = 0, count = 0;
    for (int f = 0; f + lag < frames; ++f)
      for (size_t k = 0; k < series[f].size(); ++k) both += series[f][k] * series[f + lag][k], ++count;
    rt.push_back((both / count - share * share) / var);
  }
  s.lifetime_s = e_folding(rt, dt);
  // In space: lags along z (the wind) and x (across it), on every 10th frame.
  std::vector<double> along, across;
  for (uint32_t lag = 0; lag < 64; ++lag) {
    double a = 0, c = 0, count = 0;
    for (int f = 0; f < frames; f += 10)
      for (uint32_t j = 0; j < grid; ++j)
        for (uint32_t i = 0; i < grid; ++i) {
          const uint8_t v = series[f][size_t(j) * grid + i];
          a += v * series[f][size_t((j + lag) % grid) * grid + i];
          c += v * series[f][size_t(j) * grid + (i + lag) % grid];
          ++count;
        }
    along.push_back((a / count - share * share) / var);
    across.push_back((c / count - share * share) / var);
  }
  s.along_m = e_folding(along, side / grid);
  s.across_m = e_folding(across, side / grid);
  return s;
}

}  // namespace

std::vector<uint8_t> drawn_foam(const ocean::GpuOcean& gpu, const ocean::OceanParams& p, uint32_t grid,
                                double side) {
  const ocean::FoamRule& rule = gpu.foam_rule();
  std::vector<ocean::CascadeReadback> cascades;
  for (uint32_t c = 0; c < gpu.cascade_count(); ++c) cascades.push_back(gpu.read_cascade(c));
  std::vector<uint8_t> out(size_t(grid) * grid);
  for (uint32_t j = 0; j < grid; ++j)
    for (uint32_t i = 0; i < grid; ++i) {
      double foam = 0, tx = 0, tz = 0, txz = 0;
      for (uint32_t c = 0; c < cascades.size(); ++c) {
        const uint32_t n = cascades[c].resolution;
        const double scale = n / p.cascades[c].patch_size_m;
        const size_t x = size_t(std::floor((i + 0.5) * side / grid * scale)) % n;
        const size_t z = size_t(std::floor((j + 0.5) * side / grid * scale)) % n;
        const float* t = &cascades[c].jacobian_terms[4 * (z * n + x)];
        tx += t[0], tz += t[1], txz += t[2], foam = std::max(foam, double(t[3]));
      }
      const double jacobian = (1 + tx) * (1 + tz) - txz * txz;
      foam = std::max(foam, ocean::foam_made(rule.whole.onset, rule.whole.width, jacobian));
      out[size_t(j) * grid + i] = foam >= 0.5 ? 1 : 0;
    }
  return out;
}

std::vector<Law> foam_laws(vk::Context& ctx, const ValidateOptions& o) {
  const bool lifetime_wanted = o.wants("foam.lifetime"), streaks_wanted = o.wants("foam.streaks");
  if (!lifetime_wanted && !streaks_wanted) return {};
  const std::string grid_note =
      "Fully developed JONSWAP sea, wind toward north, the default foam settings; after 15 s of steps, 100 "
      "frames at 10 Hz of the foam Lagoon draws (each cascade's and the whole sea's Jacobian's, as the "
      "surface shader combines them, whitened where >= 0.5) on a 256² grid over three times the finest "
      "cascade's patch (0.6 peak wavelengths).";
  Law lifetime{.id = "foam.lifetime",
               .title = "Whitecap foam lasts seconds",
               .source = "Callaghan, Deane & Stokes 2012 (field whitecaps: e-folding 0.5-8 s)",
               .measured_on = "device: the foam and Jacobian fields read back every step",
               .x_label = "U10 (m/s)",
               .y_label = "foam lifetime at a point (s)",
               .tolerance = "0.5-8 s",
               .log_y = true,
               .note = grid_note +
                       " Lifetime: where the autocorrelation in time of whitened-or-not, at fixed points, "
                       "falls to 1/e. Callaghan et al. (2012) found individual whitecaps' foam area "
                       "decaying quasi-exponentially with time constants of 0.5 to 8 s (Callaghan 2013: "
                       "an area-weighted mean lifetime of 5.3 s); the band is that range, its geometric "
                       "middle the reference."};
  Law streaks{
      .id = "foam.streaks",
      .title = "Foam streaks down-wind in a gale",
      .source = "Beaufort scale, forces 7-9 ('foam blown in streaks along the direction of the wind')",
      .measured_on = lifetime.measured_on,
      .x_label = "U10 (m/s)",
      .y_label = "foam length along / across the wind",
      .tolerance = ">= 1.5",
      .note = grid_note +
              " Lengths: where the foam's spatial autocorrelation along and across the wind falls to "
              "1/e. The Beaufort scale gives no number; a streak is read here as a patch at least "
              "half again as long along the wind as across it (Lagoon's reading)."};
  const std::vector<double> winds = o.quick ? std::vector<double>{14} : std::vector<double>{8, 12, 16, 20};
  for (size_t i = 0; i < winds.size(); ++i) {
    const FoamStats s = measure_foam(ctx, winds[i], o);
    lifetime.points.push_back(factor_point(winds[i], 2.0, s.lifetime_s * o.scale(), 4.0));
    if (winds[i] >= 14)  // Beaufort 7 starts at 13.9 m/s
      streaks.points.push_back(
          at_least_point(winds[i], 1.5, s.along_m / std::max(s.across_m, 1e-9) * o.scale()));
    validate_progress("foam in time", i + 1, winds.size());
  }
  return {lifetime, streaks};
}

}  // namespace lagoon::cli
