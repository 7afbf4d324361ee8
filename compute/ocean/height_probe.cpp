#include "ocean/height_probe.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <tuple>

namespace lagoon::ocean {
namespace {

struct Candidate {
  double amplitude;
  uint32_t cascade, ix, iz;
};

}  // namespace

HeightProbe::HeightProbe(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra,
                         double tolerance_m)
    : choppiness_(params.choppiness) {
  std::vector<Candidate> candidates;
  double slope_bound = 0;  // Σ |k|·a(k) over every mode: no slope of the sum exceeds it
  for (uint32_t c = 0; c < spectra.size(); ++c) {
    const CascadeSpectrum& s = spectra[c];
    const uint32_t n = s.resolution;
    const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
    axes_.push_back({dk, n, table_rows_});
    table_rows_ += n;
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix) {
        const size_t mirrored = size_t{(n - iz) % n} * n + (n - ix) % n;
        const double a = std::abs(std::complex<double>(s.h0[size_t{iz} * n + ix])) +
                         std::abs(std::complex<double>(s.h0[mirrored]));
        if (a == 0.0) continue;
        candidates.push_back({a, c, ix, iz});
        slope_bound +=
            a * dk *
            std::hypot(ix < n / 2 ? double(ix) : double(ix) - n, iz < n / 2 ? double(iz) : double(iz) - n);
      }
  }
  // The height at a displaced point errs by the height's own truncation plus the slope times the error of
  // the rest point, which the inversion amplifies by at most 2 (as in WaveQuery) from λ times the
  // displacement's truncation in each of two components.
  const double gain = 1.0 + slope_bound * 2.0 * choppiness_ * std::sqrt(2.0);
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.amplitude != b.amplitude ? a.amplitude < b.amplitude
                                      : std::tie(a.cascade, a.iz, a.ix) < std::tie(b.cascade, b.iz, b.ix);
  });
  double dropped = 0;
  size_t first_kept = 0;
  while (first_kept < candidates.size() && (dropped + candidates[first_kept].amplitude) * gain <= tolerance_m)
    dropped += candidates[first_kept++].amplitude;
  bound_m_ = dropped * gain;
  for (size_t i = first_kept; i < candidates.size(); ++i) {
    const Candidate& m = candidates[i];
    const CascadeSpectrum& s = spectra[m.cascade];
    const uint32_t n = s.resolution;
    const size_t index = size_t{m.iz} * n + m.ix, mirrored = size_t{(n - m.iz) % n} * n + (n - m.ix) % n;
    const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
    const double kx = dk * (m.ix < n / 2 ? double(m.ix) : double(m.ix) - n);
    const double kz = dk * (m.iz < n / 2 ? double(m.iz) : double(m.iz) - n);
    const double k = std::hypot(kx, kz);
    // Table row of m: m + N/2 within the cascade's rows (m = i for i < N/2, else i - N).
    const uint32_t row = axes_[m.cascade].first_row + (m.ix + n / 2) % n,
                   col = axes_[m.cascade].first_row + (m.iz + n / 2) % n;
    modes_.push_back({kx, kz, k > 0 ? 1.0 / k : 0.0, double(s.omega[index]),
                      std::complex<double>(s.h0[index]), std::conj(std::complex<double>(s.h0[mirrored])), row,
                      table_rows_ + col});
  }
}

void HeightProbe::phase_tables(const Shoaling::LatticeMoves& p,
                               std::vector<std::complex<double>>& table) const {
  table.resize(2 * size_t{table_rows_});
  for (int axis = 0; axis < 2; ++axis)
    for (size_t c = 0; c < axes_.size(); ++c) {
      const Axis& a = axes_[c];
      const glm::dvec2 at = p.point[std::min(c, Shoaling::kMaxLattices - 1)];
      const double coordinate = axis == 0 ? at.x : at.y;
      for (uint32_t r = 0; r < a.n; ++r)
        table[axis * size_t{table_rows_} + a.first_row + r] =
            std::polar(1.0, a.dk * (double(r) - double(a.n / 2)) * coordinate);
    }
}

HeightProbe::Answer HeightProbe::height(double time_s, double x, double z, const Shoaling* floor) const {
  // The evolved spectrum h̃(k,t) = h0(k)e^{-iωt} + conj(h0(-k))e^{iωt} (ocean/spectral_fields.h).
  std::vector<std::complex<double>> h(modes_.size());
  for (size_t i = 0; i < modes_.size(); ++i) {
    const std::complex<double> e = std::polar(1.0, -modes_[i].omega * time_s);
    h[i] = modes_[i].h0 * e + modes_[i].h0_mirrored_conj * std::conj(e);
  }
  // Re Σ F(k)e^{ik·p} for the height (F = h̃) and the displacement (F = i k/|k| h̃, times λ).
  std::vector<std::complex<double>> table;
  auto sum = [&](glm::dvec2 p, bool displacement) {
    // Each cascade read where its lattice has moved over the floor (ocean/shoaling.h).
    Shoaling::LatticeMoves moved;
    if (floor)
      moved = floor->lattice_moves(p);
    else
      moved.point.fill(p);
    phase_tables(moved, table);
    glm::dvec3 out(0.0);  // (Dx, h, Dz)
    for (size_t i = 0; i < modes_.size(); ++i) {
      const Mode& m = modes_[i];
      const std::complex<double> v = h[i] * table[m.phase_x] * table[m.phase_z];
      if (displacement) {
        out.x -= v.imag() * m.kx * m.inv_k;  // Re(i·v) = -Im(v)
        out.z -= v.imag() * m.kz * m.inv_k;
      } else {
        out.y += v.real();
      }
    }
    return out;
  };
  // Fixed point of p = q - λD(p): the rest position whose displaced position is q.
  const glm::dvec2 q(x, z);
  glm::dvec2 p = q;
  Answer answer{.converged = false};
  for (int iteration = 0; iteration < 32 && !answer.converged; ++iteration) {
    const glm::dvec3 d = sum(p, true) * choppiness_;
    const glm::dvec2 next = q - glm::dvec2(d.x, d.z);
    answer.converged = glm::length(next - p) < 1e-4;
    p = next;
  }
  answer.height = sum(p, false).y;
  answer.error_bound_m = bound_m_;
  return answer;
}

}  // namespace lagoon::ocean
