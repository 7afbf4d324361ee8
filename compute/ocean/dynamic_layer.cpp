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
using std::cos;
using std::exp;
using std::max;
using std::min;
using std::sin;
using std::sqrt;
using std::tanh;
#define LAGOON_FN inline
#include "shared/dynamic_layer_math.h"
#undef LAGOON_FN
}  // namespace dl_double

namespace {

using complex = std::complex<double>;

// A whole period of the grid added to or taken from a source's centre changes no phase of the grid's
// modes; kept within one period, the GPU's float phases stay accurate far from the origin.
glm::dvec2 within_period(glm::dvec2 centre, double period) {
  return centre - period * glm::floor(centre / period);
}

int cells_from_edge(int index, int origin, int n) {
  const int a = ((index - origin) % n + n) % n;  // position within the window
  return std::min(a, n - 1 - a);
}

}  // namespace

uint32_t dynamic_substeps(double dt, std::span<const WakeSource> sources) {
  double parts = 1;
  for (const WakeSource& s : sources) {
    const double narrowest = std::max(std::min(s.sigma.x, s.sigma.y), 1e-3);
    parts = std::max(parts, std::ceil(glm::length(s.velocity) * dt / (0.25 * narrowest)));
  }
  return uint32_t(std::min(parts, 64.0));
}

DynamicLayerCpu::DynamicLayerCpu(DynamicLayerParams params, unsigned threads)
    : params_(params),
      threads_(threads),
      forward_(params.n, false),
      inverse_(params.n, true),
      state_(size_t(params.n) * params.n) {}

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
  std::vector<WakeSource> local(sources.begin(), sources.end());
  for (WakeSource& s : local) s.centre = within_period(s.centre, period);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const complex z = spectrum[size_t(j) * n + i];
      const complex zm = std::conj(spectrum[size_t((n - j) % n) * n + (n - i) % n]);
      const complex h = 0.5 * (z + zm), v = (z - zm) / complex(0, 2);
      const glm::dvec2 k = dl_double::dl_wavevector(i, j, n, params_.cell_m);
      const double omega = dl_double::dl_omega(glm::length(k), params_.gravity, params_.depth_m);
      glm::dvec4 hv(h.real(), h.imag(), v.real(), v.imag());
      for (uint32_t p = 0; p < parts; ++p) {
        const double mid = (p + 0.5) * sub;
        glm::dvec2 e(0.0);
        for (const WakeSource& s : local)
          e += dl_double::dl_source_hat(k, s.centre + s.velocity * mid, s.heading, s.sigma, s.depression,
                                        s.depth, params_.cell_m);
        hv = dl_double::dl_evolve(hv, e, omega, sub, decay);
      }
      state_[size_t(j) * n + i] = scale * (complex(hv.x, hv.y) + complex(0, 1) * complex(hv.z, hv.w));
    }
  inverse_.transform(state_, 1, threads_);
  const double width = params_.sponge_m / params_.cell_m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int from_edge = std::min(cells_from_edge(i, origin_.x, n), cells_from_edge(j, origin_.y, n));
      state_[size_t(j) * n + i] *= dl_double::dl_sponge(from_edge, width, params_.sponge_per_s, dt);
    }
}

}  // namespace lagoon::ocean
