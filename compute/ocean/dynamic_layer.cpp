#include "ocean/dynamic_layer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace lagoon::ocean {
namespace dl_double {
using dl_real = double;
using dl_real2 = glm::dvec2;
using dl_real4 = glm::dvec4;
using glm::dot;
using glm::floor;
using std::clamp;
using std::cos;
using std::exp;
using std::floor;
using std::max;
using std::min;
using std::sin;
using std::sqrt;
using std::tanh;
#define LAGOON_FN inline
#include "core/compass.h"
#include "shared/dynamic_layer_math.h"
#undef LAGOON_FN
}  // namespace dl_double

namespace {

using complex = std::complex<double>;
constexpr size_t kMaxSources = 16;  // LAGOON_DYNAMIC_MAX_SOURCES, as the GPU

// A whole period of the grid added to or taken from a source's centre changes no phase of the grid's
// modes; kept within one period, the GPU's float phases stay accurate far from the origin.
glm::dvec2 within_period(glm::dvec2 centre, double period) {
  return centre - period * glm::floor(centre / period);
}

// The world cell that storage index `index` holds in a window starting at cell `origin`.
int window_cell(int index, int origin, int n) {
  return origin + ((index - origin) % n + n) % n;
}

int cells_from_edge(int index, int origin, int n) {
  const int a = ((index - origin) % n + n) % n;  // position within the window
  return std::min(a, n - 1 - a);
}

}  // namespace

double foam_spread_factor(double spread_m2_s, double cell_m, double dt) {
  return std::clamp(spread_m2_s * dt / (cell_m * cell_m), 0.0, 0.24);
}

double foam_decay_factor(double lifetime_s, double dt) {
  return lifetime_s > 0 ? std::exp(-3.0 * dt / lifetime_s) : 0.0;
}

uint32_t dynamic_substeps(double dt, std::span<const WakeSource> sources) {
  double parts = 1;
  for (const WakeSource& s : sources) {
    const double speed = glm::length(s.velocity);
    if (speed <= 0) continue;
    // The footprint's width along the motion: sigma along the heading for a hull moving ahead.
    const glm::dvec2 along = compass::toward(s.heading), across(along.y, -along.x);
    const double a = glm::dot(s.velocity, along) / speed, b = glm::dot(s.velocity, across) / speed;
    const double width = 1.0 / std::sqrt(a * a / (s.sigma.x * s.sigma.x) + b * b / (s.sigma.y * s.sigma.y));
    parts = std::max(parts, std::ceil(speed * dt / (0.25 * std::max(width, 1e-3))));
  }
  return uint32_t(std::min(parts, 64.0));
}

DynamicLayerCpu::DynamicLayerCpu(DynamicLayerParams params, unsigned threads)
    : params_(params),
      threads_(threads),
      forward_(params.n, false),
      inverse_(params.n, true),
      state_(size_t(params.n) * params.n),
      foam_(size_t(params.n) * params.n, 0.0) {}

size_t DynamicLayerCpu::index(int a, int b) const {
  const int n = int(params_.n);
  return size_t((b % n + n) % n) * params_.n + size_t((a % n + n) % n);
}

void DynamicLayerCpu::step(double dt, std::span<const WakeSource> sources) {
  const int n = int(params_.n);
  const double period = n * params_.cell_m;
  std::vector<complex> spectrum = state_;
  forward_.transform(spectrum, 1, threads_);
  const uint32_t parts = dynamic_substeps(dt, sources);
  const double sub = dt / parts, decay = std::exp(-params_.decay_per_s * sub);
  const double scale = 1.0 / (double(n) * n);
  std::vector<WakeSource> local(sources.begin(), sources.begin() + std::min(sources.size(), kMaxSources));
  for (WakeSource& s : local) s.centre = within_period(s.centre, period);
  if (turns_dt_ != sub) {
    turns_.resize(size_t(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::dvec2 k = dl_double::dl_wavevector(i, j, n, params_.cell_m);
        turns_[size_t(j) * n + i] =
            dl_double::dl_turn(dl_double::dl_omega(glm::length(k), params_.gravity, params_.depth_m), sub);
      }
    turns_dt_ = sub;
  }
  // Each source's phase e^{-i k·c} and shift e^{-i k·u dt} split into x and z factors (k = dk·(fi, fj),
  // dl_wavevector): 4n sines and cosines a source instead of 2n², which were most of the step. The products
  // agree with the whole phases to rounding.
  const double dk = 6.283185307179586 / (double(n) * params_.cell_m);
  struct Phases {
    glm::dvec2 along;
    std::vector<glm::dvec2> hat_x, hat_z, shift_x, shift_z;
  };
  std::vector<Phases> phases(local.size());
  for (size_t q = 0; q < local.size(); ++q) {
    const WakeSource& s = local[q];
    const glm::dvec2 centre = s.centre + s.velocity * (0.5 * sub);
    Phases& p = phases[q];
    p.along = compass::toward(s.heading);
    for (std::vector<glm::dvec2>* v : {&p.hat_x, &p.hat_z, &p.shift_x, &p.shift_z}) v->resize(size_t(n));
    for (int a = 0; a < n; ++a) {
      const double k = dk * double(a < n / 2 ? a : a - n);
      const auto phasor = [](double phase) { return glm::dvec2(std::cos(phase), std::sin(phase)); };
      p.hat_x[a] = phasor(-k * centre.x);
      p.hat_z[a] = phasor(-k * centre.y);
      p.shift_x[a] = phasor(-k * s.velocity.x * sub);
      p.shift_z[a] = phasor(-k * s.velocity.y * sub);
    }
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const complex z = spectrum[size_t(j) * n + i];
      // n is a power of two (dl_wavevector): the mirrored bin without an integer division.
      const complex zm = std::conj(spectrum[size_t((n - j) & (n - 1)) * n + size_t((n - i) & (n - 1))]);
      // h = (z + zm) / 2 and v = (z - zm) / 2i, written out: a complex division is a call to libgcc's
      // __divdc3 for every bin (1.7 % of `lagoon bench bodies`' profile); the same values, to a zero's sign.
      const complex h = 0.5 * (z + zm), d = z - zm, v(0.5 * d.imag(), -0.5 * d.real());
      const glm::dvec2 k = dl_double::dl_wavevector(i, j, n, params_.cell_m);
      const glm::dvec4& turn = turns_[size_t(j) * n + i];
      // The free evolution plus each source's response from rest (the step is linear), as on the GPU.
      glm::dvec4 hv(h.real(), h.imag(), v.real(), v.imag());
      for (uint32_t p = 0; p < parts; ++p) hv = dl_double::dl_evolve(hv, glm::dvec2(0.0), turn, decay);
      for (size_t q = 0; q < local.size(); ++q) {
        const WakeSource& s = local[q];
        const Phases& ph = phases[q];
        const double exponent = dl_double::dl_source_exponent(k, ph.along, s.sigma, s.depth);
        if (exponent < dl_double::kDlNegligible || (i == 0 && j == 0)) continue;  // dl_source_hat's k = 0
        glm::dvec2 e = dl_double::dl_source_magnitude(exponent, s.sigma, s.depression, params_.cell_m) *
                       dl_double::dl_complex_mul(ph.hat_x[i], ph.hat_z[j]);
        const glm::dvec2 shift = dl_double::dl_complex_mul(ph.shift_x[i], ph.shift_z[j]);
        glm::dvec4 forced(0.0);
        for (uint32_t p = 0; p < parts; ++p) {
          forced = dl_double::dl_evolve(forced, e, turn, decay);
          e = dl_double::dl_complex_mul(e, shift);
        }
        hv += forced;
      }
      state_[size_t(j) * n + i] = scale * complex(hv.x - hv.w, hv.y + hv.z);  // h + i v
    }
  inverse_.transform(state_, 1, threads_);
  const double width = params_.sponge_m / params_.cell_m;
  const double foam_decay = foam_decay_factor(params_.foam_lifetime_s, dt);
  const double spread = foam_spread_factor(params_.foam_spread_m2_s, params_.cell_m, dt);
  if (foam_on_) previous_foam_ = foam_;  // each cell spreads from its neighbours' foam before this step
  // The sponge's factor depends on the distance to the nearest edge alone: one exp per distance.
  std::vector<double> sponge_at(size_t(n / 2 + 1));
  for (int e = 0; e <= n / 2; ++e) sponge_at[e] = dl_double::dl_sponge(e, width, params_.sponge_per_s, dt);
  std::vector<int> column_edge(n), row_edge(n);
  for (int a = 0; a < n; ++a) {
    column_edge[a] = cells_from_edge(a, origin_.x, n);
    row_edge[a] = cells_from_edge(a, origin_.y, n);
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double sponge = sponge_at[size_t(std::min(column_edge[i], row_edge[j]))];
      const size_t c = size_t(j) * n + i;
      state_[c] *= sponge;
      if (!foam_on_) continue;
      // The cell's world position: its index within the window, from the window's first cell.
      const glm::dvec2 xz =
          glm::dvec2(window_cell(i, origin_.x, n), window_cell(j, origin_.y, n)) * params_.cell_m;
      double injected = 0;
      for (const WakeSource& s : local)
        injected += dl_double::dl_foam_injection(xz, s.centre, s.velocity, compass::toward(s.heading),
                                                 s.sigma, s.foam_per_s, dt, period);
      const auto at = [&](int a, int b) { return previous_foam_[size_t(b & (n - 1)) * n + (a & (n - 1))]; };
      const double spread_foam = dl_double::dl_foam_spread(
          previous_foam_[c], at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1), spread);
      foam_[c] = dl_double::dl_foam_update(spread_foam, foam_decay, injected) * sponge;
    }
}

}  // namespace lagoon::ocean
