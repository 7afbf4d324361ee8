#include "ocean/shoaling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <queue>
#include <stdexcept>

#include "ocean/ocean_params.h"

namespace {
using sh_real = double;
using sh_real2 = glm::dvec2;
using sh_real4 = glm::dvec4;
using glm::dot;
using std::clamp;
using std::floor;
using std::max;
using std::min;
#define LAGOON_FN inline
#include "shared/shoaling_math.h"
#undef LAGOON_FN

// Depths below this are treated as this for the wavenumber (k ~ 1/sqrt(h) grows without bound at the
// shoreline, where the wave has already broken down to nothing).
constexpr double kShallowestM = 0.02;
// Where rays cross (behind a shoal) linear theory's amplitude is infinite; it is held to this many a0.
constexpr double kMostFocusing = 4.0;
}  // namespace

namespace lagoon::ocean {

double Shoaling::wavenumber(double omega, double depth_m) {
  const double deep = omega * omega / kGravity;
  if (!(depth_m > 0)) return HUGE_VAL;
  // Newton on f(k) = g k tanh(k h) - ω², from k0 / sqrt(tanh(k0 h)), within 5 % everywhere.
  double k = deep / std::sqrt(std::tanh(deep * depth_m));
  for (int i = 0; i < 50; ++i) {
    const double t = std::tanh(k * depth_m);
    const double f = kGravity * k * t - omega * omega;
    const double df = kGravity * (t + k * depth_m * (1 - t * t));
    const double step = f / df;
    k -= step;
    if (std::abs(step) < 1e-15 * k) break;
  }
  return k;
}

double Shoaling::group_velocity(double omega, double depth_m) {
  const double k = wavenumber(omega, depth_m);
  const double kh2 = 2 * k * depth_m;
  const double n = 0.5 * (1 + (kh2 > 40 ? 0.0 : kh2 / std::sinh(kh2)));
  return n * omega / k;
}

namespace {

// A wave's linear theory at one depth, relative to where it is its own (`top`: half its wavelength down, or
// the depth a finite-depth wave is given at), so that it is continuous there and exact for a finite-depth
// wave: its wavenumber and its group velocity over the one at `top`.
struct LocalTheory {
  double k = 0, cg_ratio = 1;
  bool own = true;  // deeper than top: the wave as it is
};
struct WaveTheory {
  double k0, omega, top, k_top, cg_top;
  WaveTheory(const ShoalingWave& w, double reference_depth_m)
      : k0(glm::length(w.k)),
        omega(w.omega),
        top(std::min({std::numbers::pi / k0, reference_depth_m, w.own_depth_m})),
        k_top(Shoaling::wavenumber(omega, top)),
        cg_top(Shoaling::group_velocity(omega, top)) {}
  LocalTheory at(double h) const {
    if (h >= top) return {k0, 1.0, true};
    const double he = std::max(h, kShallowestM);
    return {k0 * Shoaling::wavenumber(omega, he) / k_top, Shoaling::group_velocity(omega, he) / cg_top,
            false};
  }
};

}  // namespace

Shoaling::Shoaling(ShoalingInputs inputs) : inputs_(std::move(inputs)) {
  const DepthProfile* floor = inputs_.floor.get();
  if (!floor || floor->rows == 0 || floor->columns() < 2 ||
      floor->columns() * floor->rows != floor->depth_m.size() || !(floor->spacing_m > 0))
    throw std::invalid_argument("Shoaling: the depth grid needs two samples or more along u, > 0 apart");
  if (lattice_count() > kMaxLattices) throw std::invalid_argument("Shoaling: more cascades than it moves");
  const size_t n = samples(), waves = wave_count();
  table_.assign(n * (1 + waves + lattice_count()), glm::dvec4(0.0));
  for (const ShoalingWave& w : inputs_.sea.lattice) {
    const double k2 = glm::dot(w.k, w.k);
    lattice_waves_.push_back(k2 > 0 ? glm::dvec4(w.k, w.k / k2) : glm::dvec4(0.0));
  }
  // The random sea's lattices: their moves, and their shoaling, the energy-weighted K_s K_r of their
  // representative waves: sqrt(Σ a_c² / Σ a0_c²), 1 where all are their own.
  std::vector<double> energy(n, 0.0);
  double own_energy = 0;
  for (size_t c = 0; c < lattice_count(); ++c) {
    const ShoalingWave& w = inputs_.sea.lattice[c];
    if (glm::length(w.k) == 0) continue;  // no waves: not moved (zeros)
    const size_t layer = lattice_layer(c);
    const std::vector<double> a = floor->rows == 1 ? build_profile_wave(layer) : build_grid_wave(layer);
    own_energy += w.amplitude_m * w.amplitude_m;
    for (size_t j = 0; j < n; ++j) {
      table_[layer * n + j].y = a[j];
      energy[j] += a[j] * a[j];
      if (table_[layer * n + j].x != 0 || a[j] != w.amplitude_m) active_ = true;
    }
  }
  std::vector<double> linear(n, 0.0);  // Σ H_i before breaking
  for (size_t i = 0; i < waves; ++i) {
    const std::vector<double> a = floor->rows == 1 ? build_profile_wave(1 + i) : build_grid_wave(1 + i);
    const ShoalingWave& w = inputs_.waves[i];
    for (size_t j = 0; j < n; ++j) {
      linear[j] += w.height_per_amplitude * a[j];
      // Breaking: no higher than γ h, nothing on dry land.
      table_[(1 + i) * n + j].y =
          std::min(a[j], inputs_.breaker_index * std::max(floor->depth_m[j], 0.0) / w.height_per_amplitude);
      if (a[j] != w.amplitude_m) active_ = true;
    }
  }
  double base_steepness = 0;
  for (const ShoalingWave& w : inputs_.waves)
    base_steepness += w.steepness * glm::length(w.k) * w.amplitude_m;
  const double hs = inputs_.sea.significant_height_m, gamma = inputs_.breaker_index;
  for (size_t j = 0; j < n; ++j) {
    const double h = floor->depth_m[j], cap = gamma * std::max(h, 0.0);
    // The waves' sum breaks too: where their summed height exceeds γ h each is scaled down alike.
    double summed = 0, steep = 0;
    for (size_t i = 0; i < waves; ++i)
      summed += inputs_.waves[i].height_per_amplitude * table_[(1 + i) * n + j].y;
    const double together = summed > cap ? (summed > 0 ? cap / summed : 0.0) : 1.0;
    for (size_t i = 0; i < waves; ++i) {
      glm::dvec4& v = table_[(1 + i) * n + j];
      if (together < 1) v.y *= together;
      steep += inputs_.waves[i].steepness * glm::length(glm::dvec2(v.z, v.w)) * v.y;
    }
    // Steeper, shorter waves would loop their crests: never more than the waves do in deep water (or 1).
    const double allowed = std::max(1.0, base_steepness);
    const double q = steep > allowed ? allowed / steep : 1.0;
    // The random sea grows as its waves shoal, up to its depth limit (0.6 h), and ends at the shoreline.
    const double shoaled = own_energy > 0 ? std::sqrt(energy[j] / own_energy) : 1.0;
    const double sea = hs > 0 ? std::clamp(kSurfZoneHsPerDepth * h / hs, 0.0, shoaled) : 1.0;
    const double ratio = cap > 0 ? linear[j] / cap : (linear[j] > 0 ? 1e3 : 0.0);
    table_[j] = glm::dvec4(h, sea, q, ratio);
    if (sea != 1 || q < 1) active_ = true;
  }
}

// Straight, parallel contours: k_v is conserved (Snell's law), k_u = sqrt(k² - k_v²), the amplitude
// a0 K_s K_r, and φ(s) = ∫ (k_u - k_u0) ds (trapezoids: the shaders interpolate linearly), 0 at the deepest
// sample.
std::vector<double> Shoaling::build_profile_wave(size_t layer) {
  const ShoalingWave& w = layer_wave(layer);
  const DepthProfile& floor = *inputs_.floor;
  const size_t n = samples();
  const WaveTheory theory(w, inputs_.reference_depth_m);
  const glm::dvec2 u = floor.axis, v = floor.across();
  const double ku0 = glm::dot(w.k, u), kv = glm::dot(w.k, v), cos0 = std::abs(ku0) / theory.k0;
  glm::dvec4* row = &table_[layer * n];
  std::vector<double> amplitude(n, w.amplitude_m);
  for (size_t j = 0; j < n; ++j) {
    const double h = floor.depth_m[j];
    const LocalTheory local = theory.at(h);
    double ku = ku0;
    if (!local.own) {
      ku = std::copysign(std::sqrt(std::max(local.k * local.k - kv * kv, 0.0)), ku0 == 0 ? 1.0 : ku0);
      const double cos_theta = std::abs(ku) / local.k;
      const double refraction = cos_theta > 0 ? std::sqrt(cos0 / cos_theta) : 1.0;
      amplitude[j] = h > 0 ? w.amplitude_m * refraction / std::sqrt(local.cg_ratio) : 0.0;
    }
    row[j] = glm::dvec4(0.0, 0.0, ku, kv);
  }
  const size_t anchor =
      size_t(std::max_element(floor.depth_m.begin(), floor.depth_m.end()) - floor.depth_m.begin());
  const double half = 0.5 * floor.spacing_m;
  for (size_t j = anchor + 1; j < n; ++j)
    row[j].x = row[j - 1].x + half * (row[j - 1].z + row[j].z - 2 * ku0);
  for (size_t j = anchor; j-- > 0;) row[j].x = row[j + 1].x - half * (row[j + 1].z + row[j].z - 2 * ku0);
  return amplitude;
}

// Any floor on the grid: the phase S by fast marching |∇S| = k(h) from the cells where the wave is its own
// (deeper than `top`) and from the grid's upwind edges, where S = k0·x; the local wavevector is k(h) along
// ∇S; the amplitude by marching the energy flux along the rays in the same order: d ln(E c_g)/ds = -∇·k̂.
std::vector<double> Shoaling::build_grid_wave(size_t layer_index) {
  const ShoalingWave& w = layer_wave(layer_index);
  const DepthProfile& floor = *inputs_.floor;
  const size_t nu = floor.columns(), nv = floor.rows, n = samples();
  const double d = floor.spacing_m;
  const WaveTheory theory(w, inputs_.reference_depth_m);
  const glm::dvec2 k0(glm::dot(w.k, floor.axis), glm::dot(w.k, floor.across()));  // in (u, v)
  std::vector<LocalTheory> local(n);
  for (size_t c = 0; c < n; ++c) local[c] = theory.at(floor.depth_m[c]);
  auto plane = [&](size_t i, size_t j) { return k0.x * d * double(i) + k0.y * d * double(j); };

  // Fast marching (first order, Sethian 1996) from the cells where the wave is its own; where there are none
  // (the whole grid is shallow for this wave), from the edges it enters by, as if it arrived there as it is.
  std::vector<double> phase(n, HUGE_VAL);
  std::vector<char> fixed(n, 0), source(n, 0);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> front;
  const bool any_own = std::any_of(local.begin(), local.end(), [](const LocalTheory& l) { return l.own; });
  for (size_t j = 0; j < nv; ++j)
    for (size_t i = 0; i < nu; ++i) {
      const bool upwind = !any_own && ((k0.x > 0 && i == 0) || (k0.x < 0 && i == nu - 1) ||
                                       (k0.y > 0 && j == 0) || (k0.y < 0 && j == nv - 1));
      const size_t c = j * nu + i;
      if (local[c].own || upwind) {
        source[c] = 1;
        phase[c] = plane(i, j);
        front.push({phase[c], c});
      }
    }
  std::vector<size_t> order;  // cells in the order their phase was settled
  order.reserve(n);
  auto update = [&](size_t i, size_t j) {
    const size_t c = j * nu + i;
    if (fixed[c]) return;
    auto best = [&](size_t a, bool ok_a, size_t b, bool ok_b) {
      double m = HUGE_VAL;
      if (ok_a && fixed[a]) m = std::min(m, phase[a]);
      if (ok_b && fixed[b]) m = std::min(m, phase[b]);
      return m;
    };
    const double a = best(c - 1, i > 0, c + 1, i + 1 < nu);
    const double b = best(c - nu, j > 0, c + nu, j + 1 < nv);
    const double f = local[c].k * d;
    double s;
    if (std::isfinite(a) && std::isfinite(b) && std::abs(a - b) < f)
      s = 0.5 * (a + b + std::sqrt(2 * f * f - (a - b) * (a - b)));
    else
      s = std::min(a, b) + f;
    if (s < phase[c]) {
      phase[c] = s;
      front.push({s, c});
    }
  };
  while (!front.empty()) {
    const auto [s, c] = front.top();
    front.pop();
    if (fixed[c] || s > phase[c]) continue;
    fixed[c] = 1;
    order.push_back(c);
    const size_t i = c % nu, j = c / nu;
    if (i > 0) update(i - 1, j);
    if (i + 1 < nu) update(i + 1, j);
    if (j > 0) update(i, j - 1);
    if (j + 1 < nv) update(i, j + 1);
  }

  // The direction from ∇S (central differences, one-sided at the edges), the magnitude from the dispersion.
  std::vector<glm::dvec2> dir(n);
  auto gradient = [&](size_t i, size_t j) {
    const size_t il = i > 0 ? i - 1 : i, ir = i + 1 < nu ? i + 1 : i, jl = j > 0 ? j - 1 : j,
                 jr = j + 1 < nv ? j + 1 : j;
    return glm::dvec2((phase[j * nu + ir] - phase[j * nu + il]) / (d * double(ir - il)),
                      (phase[jr * nu + i] - phase[jl * nu + i]) / (d * double(jr - jl)));
  };
  glm::dvec4* layer = &table_[layer_index * n];
  for (size_t j = 0; j < nv; ++j)
    for (size_t i = 0; i < nu; ++i) {
      const size_t c = j * nu + i;
      const glm::dvec2 g = local[c].own ? k0 : gradient(i, j);
      dir[c] = glm::length(g) > 0 ? g / glm::length(g) : k0 / theory.k0;
      const glm::dvec2 k = local[c].own ? k0 : dir[c] * local[c].k;
      layer[c] = glm::dvec4(phase[c] - plane(i, j), 0.0, k.x, k.y);
    }
  // ∇·k̂, central differences.
  std::vector<double> divergence(n, 0.0);
  for (size_t j = 0; j < nv; ++j)
    for (size_t i = 0; i < nu; ++i) {
      const size_t il = i > 0 ? i - 1 : i, ir = i + 1 < nu ? i + 1 : i, jl = j > 0 ? j - 1 : j,
                   jr = j + 1 < nv ? j + 1 : j;
      divergence[j * nu + i] =
          (dir[j * nu + ir].x - dir[j * nu + il].x) / (d * double(std::max<size_t>(ir - il, 1))) +
          (dir[jr * nu + i].y - dir[jl * nu + i].y) / (d * double(std::max<size_t>(jr - jl, 1)));
    }
  // F = ln(a² c_g / c_g,top) along the rays, in the marching order: each cell from the point one spacing
  // back along its ray, interpolated between the cells settled before it.
  std::vector<double> flux(n, 0.0);
  std::vector<char> done(n, 0);
  std::vector<double> amplitude(n, w.amplitude_m);
  const double own_flux = 2 * std::log(w.amplitude_m);
  for (const size_t c : order) {
    const size_t i = c % nu, j = c / nu;
    if (source[c]) {
      flux[c] = own_flux;  // its own, or entering the grid as it is in deep water (K_s applies from here)
    } else {
      const glm::dvec2 back = glm::dvec2(double(i), double(j)) - dir[c];
      const double bu = std::clamp(back.x, 0.0, double(nu - 1)), bv = std::clamp(back.y, 0.0, double(nv - 1));
      const size_t i0 = std::min(size_t(bu), nu - 2), j0 = std::min(size_t(bv), nv - 2);
      const double fu = bu - double(i0), fv = bv - double(j0);
      double sum = 0, weight = 0;
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const size_t cc = (j0 + dj) * nu + (i0 + di);
          if (j0 + dj >= nv || !done[cc]) continue;
          const double wgt = (di ? fu : 1 - fu) * (dj ? fv : 1 - fv) + 1e-9;
          sum += wgt * flux[cc];
          weight += wgt;
        }
      flux[c] = (weight > 0 ? sum / weight : own_flux) - divergence[c] * d;
    }
    done[c] = 1;
    const double h = floor.depth_m[c];
    if (!local[c].own)
      amplitude[c] =
          h > 0 ? std::min(std::sqrt(std::exp(flux[c]) / local[c].cg_ratio), kMostFocusing * w.amplitude_m)
                : 0.0;
  }
  return amplitude;
}

Shoaling::Where Shoaling::locate(glm::dvec2 xz) const {
  const DepthProfile& floor = *inputs_.floor;
  const glm::dvec2 s = floor.local(xz);
  const glm::dvec4 u = sh_locate(s.x, floor.spacing_m, double(floor.columns()));
  const glm::dvec4 v = sh_locate(s.y, floor.spacing_m, double(floor.rows));
  Where w;
  w.i0 = size_t(u.x);
  w.i1 = std::min(w.i0 + 1, floor.columns() - 1);
  w.j0 = size_t(v.x);
  w.j1 = std::min(w.j0 + 1, floor.rows - 1);
  w.fu = u.y;
  w.fv = v.y;
  w.beyond_u = u.z;
  w.beyond_v = v.z;
  return w;
}

glm::dvec4 Shoaling::at(size_t layer, const Where& w) const {
  const size_t nu = inputs_.floor->columns();
  const glm::dvec4* t = &table_[layer * samples()];
  return sh_bilinear(t[w.j0 * nu + w.i0], t[w.j0 * nu + w.i1], t[w.j1 * nu + w.i0], t[w.j1 * nu + w.i1], w.fu,
                     w.fv);
}

glm::dvec4 Shoaling::ground(glm::dvec2 xz) const {
  return at(0, locate(xz));
}

const ShoalingWave& Shoaling::layer_wave(size_t layer) const {
  return layer <= wave_count() ? inputs_.waves[layer - 1] : inputs_.sea.lattice[layer - 1 - wave_count()];
}

glm::dvec4 Shoaling::wave_at(size_t layer, const ShoalingWave& wave, const Where& w) const {
  const DepthProfile& floor = *inputs_.floor;
  return sh_wave_value(at(layer, w), w.beyond_u, w.beyond_v, glm::dot(wave.k, floor.axis),
                       glm::dot(wave.k, floor.across()));
}

glm::dvec4 Shoaling::wave(size_t i, glm::dvec2 xz) const {
  return wave_at(1 + i, inputs_.waves[i], locate(xz));
}

glm::dvec4 Shoaling::lattice_wave(size_t c) const {
  return c < lattice_waves_.size() ? lattice_waves_[c] : glm::dvec4(0.0);
}

Shoaling::LatticeMoves Shoaling::lattice_moves(glm::dvec2 xz) const {
  LatticeMoves moves;
  moves.point.fill(xz);
  moves.grad.fill(glm::dvec2(0.0));
  const Where w = locate(xz);
  moves.sea_scale = at(0, w).y;
  for (size_t c = 0; c < lattice_count(); ++c) {
    const ShoalingWave& wave = inputs_.sea.lattice[c];
    if (wave.k == glm::dvec2(0.0)) continue;
    const glm::dvec4 value = wave_at(lattice_layer(c), wave, w);
    moves.point[c] = sh_lattice_point(xz, value.x, lattice_waves_[c]);
    moves.grad[c] = wavevector(value) - wave.k;
  }
  return moves;
}

glm::dvec2 Shoaling::lattice_slope(size_t c, const LatticeMoves& moves, glm::dvec2 slope) const {
  return sh_lattice_slope(slope, moves.grad[c], lattice_wave(c));
}

glm::dvec2 Shoaling::wavevector(const glm::dvec4& value) const {
  return value.z * inputs_.floor->axis + value.w * inputs_.floor->across();
}

}  // namespace lagoon::ocean
