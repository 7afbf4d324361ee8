#include "validate_wakes.h"

#include <algorithm>
#include <cmath>

#include "ocean/dynamic_layer.h"

namespace lagoon::cli {
namespace {

// The hull: a Gaussian footprint of σ = 2 m along its heading and 1 m across, so L = 4σ = 8 m (the length
// that holds 95 % of its depression), and Fr = U / √(g L).
constexpr double kSigmaAlong = 2.0, kSigmaAcross = 1.0, kHullLength = 4 * kSigmaAlong;

struct WakeShot {
  double cusp_deg = 0;      // the outermost envelope peak's line (Kelvin's cusps)
  double peak_deg = 0;      // the line of the envelope's largest off-track peak (Rabaud & Moisy's angle)
  double transverse_m = 0;  // crest spacing along the track
};

// |h| across the track at `behind` metres behind the hull, the largest within ±4 cells along it, for
// η = 0 .. 0.7 behind on one side.
std::vector<double> wake_envelope(const ocean::DynamicLayerCpu& layer, glm::dvec2 hull, double cell,
                                  double behind, int side) {
  const int a = int(std::lround((hull.x + behind) / cell));
  std::vector<double> e;
  for (double eta = 0; eta <= 0.7 * behind; eta += cell) {
    const int b = int(std::lround((hull.y + side * eta) / cell));
    double m = 0;
    for (int da = -4; da <= 4; ++da) m = std::max(m, std::abs(layer.height(a + da, b)));
    e.push_back(m);
  }
  return e;
}

// Least-squares slope through the origin-free line η(behind), as an angle.
double fitted_angle_deg(const std::vector<glm::dvec2>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const glm::dvec2& p : points) sx += p.x, sy += p.y, sxx += p.x * p.x, sxy += p.x * p.y;
  const double n = double(points.size());
  return std::atan((n * sxy - sx * sy) / (n * sxx - sx * sx)) * 180 / kPi;
}

// The dominant wavelength of h along the track, `from_m` .. `to_m` behind the hull (averaged over ±1 cell
// across it): the peak of a Hann-windowed periodogram scanned over 0.3 to 3 times `guess_m` in 1 % steps.
// Crest counting would be fooled by the diverging waves, which cross the track with shorter spacings.
double track_wavelength(const ocean::DynamicLayerCpu& layer, glm::dvec2 hull, double cell, double from_m,
                        double to_m, double guess_m) {
  const int row = int(std::lround(hull.y / cell));
  std::vector<double> xs, hs;
  for (double behind = from_m; behind <= to_m; behind += cell / 2) {
    const double x = (hull.x + behind) / cell;
    const int a = int(std::floor(x));
    const double f = x - a;
    double h = 0;
    for (int db = -1; db <= 1; ++db)
      h += (1 - f) * layer.height(a, row + db) + f * layer.height(a + 1, row + db);
    xs.push_back(behind), hs.push_back(h);
  }
  double best = 0, best_power = -1;
  for (double lambda = 0.3 * guess_m; lambda <= 3.0 * guess_m; lambda *= 1.01) {
    double re = 0, im = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
      const double w = 0.5 - 0.5 * std::cos(2 * kPi * double(i) / double(xs.size() - 1));
      re += w * hs[i] * std::cos(2 * kPi * xs[i] / lambda),
          im += w * hs[i] * std::sin(2 * kPi * xs[i] / lambda);
    }
    if (re * re + im * im > best_power) best_power = re * re + im * im, best = lambda;
  }
  return best;
}

// The layer (deep water, no damping) after a hull has run at Froude number `froude` long enough for its
// steady wake to fill `to_m` metres behind it: the waves' energy falls behind the hull at their group
// velocity, half of U, so the pattern is steady up to half the distance run. The window follows the hull,
// 20 m from its front edge. Each mode is advanced exactly, so the step of 0.2 s is as good as 0.1 s (the
// angles agree within 0.2°); the forcing is split finer by the layer itself.
WakeShot run_wake(double froude, uint32_t n, double cell, double from_m, double to_m,
                  const ValidateOptions& o) {
  const double speed = froude * std::sqrt(kG * kHullLength), dt = 0.2;
  // The broken variant: water so shallow that the hull runs at a depth Froude number of 0.9, where Kelvin's
  // deep-water pattern does not hold (Havelock: the wedge widens and the transverse waves lengthen).
  const double depth = o.broken == "shallow-wakes" ? speed * speed / (kG * 0.81) : 0.0;
  ocean::DynamicLayerParams p{.n = n, .cell_m = cell, .depth_m = depth, .decay_per_s = 0, .sponge_m = 12};
  ocean::DynamicLayerCpu layer(p, 2);
  ocean::WakeSource hull{.centre = {20, 0.5 * n * cell},
                         .velocity = {-speed, 0},
                         .heading = -kPi / 2,
                         .sigma = {kSigmaAlong, kSigmaAcross},
                         .depression = 0.3};
  const int steps = int(std::ceil(2 * (to_m + 20) / speed / dt));
  for (int s = 0; s < steps; ++s) {
    layer.set_window({int(std::floor((hull.centre.x - 20) / cell)), 0});
    layer.step(dt, {&hull, 1});
    hull.centre += hull.velocity * dt;
  }
  WakeShot shot;
  std::vector<glm::dvec2> cusps, peaks;
  for (double behind = from_m; behind <= to_m; behind += 1.0)
    for (int side : {-1, 1}) {
      const std::vector<double> e = wake_envelope(layer, hull.centre, cell, behind, side);
      const double top = *std::max_element(e.begin(), e.end());
      // Kelvin's cusp: the outermost local maximum above 40 % of the row's largest (beyond it the pattern
      // dies away, inside it the transverse waves take over). Rabaud & Moisy's angle: the largest one.
      size_t cusp = 0, peak = 0;
      for (size_t i = e.size() - 2; i > 0; --i)
        if (e[i] >= 0.4 * top && e[i] >= e[i - 1] && e[i] >= e[i + 1]) {
          cusp = i;
          break;
        }
      for (size_t i = 1; i + 1 < e.size(); ++i)
        if (e[i] >= e[i - 1] && e[i] >= e[i + 1] && e[i] > e[peak]) peak = i;
      cusps.push_back({behind, double(cusp) * cell});
      peaks.push_back({behind, double(peak) * cell});
    }
  shot.cusp_deg = fitted_angle_deg(cusps);
  shot.peak_deg = fitted_angle_deg(peaks);
  shot.transverse_m = track_wavelength(layer, hull.centre, cell, from_m, to_m, 2 * kPi * speed * speed / kG);
  return shot;
}

}  // namespace

std::vector<Law> wake_laws(const ValidateOptions& o) {
  if (!o.wants("wakes")) return {};
  Law kelvin{
      .id = "wakes.kelvin-angle",
      .title = "Kelvin's wake half-angle below Fr 0.5",
      .source = "Kelvin 1887; Rabaud & Moisy 2013",
      .measured_on =
          "cpu: the dynamic wave layer the bodies feel (ocean/dynamic_layer.h), the GPU's reference",
      .x_label = "Fr = U / sqrt(g L)",
      .y_label = "cusp half-angle (deg)",
      .tolerance = "±2°",
      .note =
          "A hull of Gaussian footprint (sigma 2 m along, 1 m across: L = 4 sigma = 8 m) at constant speed "
          "in deep, undamped water, 0.5 m cells; the cusps are the outermost peaks of |h| across the "
          "track (above 40 % of the row's largest), fitted from 20 to 80 m behind. Below Fr 0.35 the "
          "hull is long against its waves, which it barely makes (their amplitude falls as "
          "exp(-k^2 sigma^2 / 2)), and the cusps sink under the transverse waves."};
  Law transverse{
      .id = "wakes.transverse-wavelength",
      .title = "Transverse wavelength 2 pi U^2 / g",
      .source = "Kelvin 1887 (the wave that keeps pace with the hull: c = U)",
      .measured_on = kelvin.measured_on,
      .x_label = "U (m/s)",
      .y_label = "wavelength along the track (m)",
      .tolerance = "±10 %",
      .note = "The same runs; the peak of the periodogram of h along the track, 20 to 80 m behind."};
  Law narrowing{
      .id = "wakes.narrowing",
      .title = "The wake narrows above Fr 0.5",
      .source = "Rabaud & Moisy 2013; Darmon, Benzaquen & Raphael 2014 (eq. 4.11, Gaussian source)",
      .measured_on = kelvin.measured_on,
      .x_label = "Fr = U / sqrt(g L)",
      .y_label = "angle of the largest waves (deg)",
      .tolerance = "±15 %",
      .note =
          "The same hull, faster: the angle of the line of largest |h| across the track, fitted from 40 "
          "to 200 m behind (1 m cells, or 0.5 m in the full run). Reference: Darmon et al.'s angle of "
          "maximum amplitude for a Gaussian pressure, theta = 0.2243 / Fr_b with b = pi sqrt(2) sigma, "
          "i.e. 0.473 sqrt(g sigma) / U, with sigma the footprint's across the track (the diverging "
          "waves at small angles travel almost across it). Rabaud & Moisy's ships give about "
          "0.2 / Fr, 13 % wider than this at every speed. At Fr 0.7 the largest waves are still near the "
          "cusps (18°): the crossover between the two regimes, where neither law applies, is left out."};
  std::vector<double> slow, fast;
  if (o.wants(kelvin.id) || o.wants(transverse.id))
    slow = o.quick ? std::vector<double>{0.45} : std::vector<double>{0.35, 0.4, 0.45, 0.5};
  if (o.wants(narrowing.id))
    fast = o.quick ? std::vector<double>{1.0} : std::vector<double>{1.0, 1.4, 2.0, 2.8};
  size_t done = 0;
  const size_t total = slow.size() + fast.size();
  for (double fr : slow) {
    const WakeShot shot = run_wake(fr, 256, 0.5, 20, 80, o);
    const double speed = fr * std::sqrt(kG * kHullLength);
    kelvin.points.push_back(
        absolute_point(fr, std::asin(1.0 / 3.0) * 180 / kPi, shot.cusp_deg * o.scale(), 2.0));
    transverse.points.push_back(
        relative_point(speed, 2 * kPi * speed * speed / kG, shot.transverse_m * o.scale(), 0.10));
    validate_progress("wakes", ++done, total);
  }
  for (double fr : fast) {
    const WakeShot shot = o.quick ? run_wake(fr, 256, 1.0, 40, 200, o) : run_wake(fr, 512, 0.5, 40, 200, o);
    const double speed = fr * std::sqrt(kG * kHullLength);
    const double darmon = 0.4729 * std::sqrt(kG * kSigmaAcross) / speed * 180 / kPi;
    narrowing.points.push_back(relative_point(fr, darmon, shot.peak_deg * o.scale(), 0.15));
    validate_progress("wakes", ++done, total);
  }
  return {kelvin, transverse, narrowing};
}

}  // namespace lagoon::cli
