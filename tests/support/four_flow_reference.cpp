#include "support/four_flow_reference.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lagoon::test {
namespace {

using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j) c[i][j] += a[i][k] * b[k][j];
  return c;
}

// exp(A): scale A until its norm is below 1/4, 20 Taylor terms (truncation < 1e-30), square back.
Mat4 expm(Mat4 a) {
  double norm = 0;
  for (const auto& row : a) {
    double sum = 0;
    for (double v : row) sum += std::fabs(v);
    norm = std::max(norm, sum);
  }
  int squarings = 0;
  while (norm > 0.25) {
    norm *= 0.5;
    ++squarings;
  }
  for (auto& row : a)
    for (double& v : row) v = std::ldexp(v, -squarings);
  Mat4 result{}, term{};
  for (int i = 0; i < 4; ++i) result[i][i] = term[i][i] = 1.0;
  for (int n = 1; n <= 20; ++n) {
    term = multiply(term, a);
    for (auto& row : term)
      for (double& v : row) v /= n;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) result[i][j] += term[i][j];
  }
  for (int s = 0; s < squarings; ++s) result = multiply(result, result);
  return result;
}

// A banded matrix solved by Gaussian elimination with partial pivoting (as LAPACK's gbsv): row r stores
// columns r − kl .. r + kl + ku, the extra kl for the fill-in that row swaps bring.
class BandSystem {
 public:
  BandSystem(int n, int kl, int ku)
      : n_(n), kl_(kl), width_(2 * kl + ku + 1), a_(size_t(n) * width_), b_(n) {}
  double& at(int r, int c) { return a_[size_t(r) * width_ + (c - r + kl_)]; }
  double& rhs(int r) { return b_[r]; }

  std::vector<double> solve() {
    const int reach = width_ - kl_ - 1;  // columns right of the diagonal a row may hold after swaps
    for (int j = 0; j < n_; ++j) {
      const int last = std::min(n_ - 1, j + kl_);
      int pivot = j;
      for (int i = j + 1; i <= last; ++i)
        if (std::fabs(at(i, j)) > std::fabs(at(pivot, j))) pivot = i;
      const int end = std::min(n_ - 1, j + reach);
      if (pivot != j) {
        for (int c = j; c <= end; ++c) std::swap(at(j, c), at(pivot, c));
        std::swap(b_[j], b_[pivot]);
      }
      for (int i = j + 1; i <= last; ++i) {
        const double factor = at(i, j) / at(j, j);
        if (factor == 0.0) continue;
        for (int c = j; c <= end; ++c) at(i, c) -= factor * at(j, c);
        b_[i] -= factor * b_[j];
      }
    }
    std::vector<double> x(n_);
    for (int j = n_ - 1; j >= 0; --j) {
      double sum = b_[j];
      for (int c = j + 1; c <= std::min(n_ - 1, j + reach); ++c) sum -= at(j, c) * x[c];
      x[j] = sum / at(j, j);
    }
    return x;
  }

 private:
  int n_, kl_, width_;
  std::vector<double> a_, b_;
};

}  // namespace

FourFlowProfile solve_four_flow_reference(const optics::FourFlowInput& in, int segments) {
  // The seed's constants below eq. 4, recomputed here rather than taken from the closed form.
  const double eps = in.absorption_per_m + in.scattering_per_m;
  const double k = in.absorption_per_m / eps, sp = in.scattering_per_m / eps, x1 = in.phase_x1;
  const double s = sp * (1.0 - 0.5 * x1), s1 = 0.5 * sp * (1.0 + x1), s2 = 0.5 * sp * (1.0 - x1);
  const double lambda = k + s1 + s2;
  const double tau0 = eps * in.depth_m;

  int n = std::max({segments, 2, int(std::ceil(tau0 / 0.5))});
  n += n % 2;
  FourFlowProfile out;
  out.step = tau0 / n;
  // y' = K y, y = (G+, G−, F+, F−): eq. 4 as printed.
  // The diffuse path-length factor D scales the diffuse rows' own terms (1 in the seed).
  const double d = in.diffuse_path_factor;
  const Mat4 kmat = {{{-lambda, 0, 0, 0},
                      {0, lambda, 0, 0},
                      {s1, s2, -d * (k + s), d * s},
                      {-s2, -s1, -d * s, d * (k + s)}}};
  Mat4 scaled = kmat;
  for (auto& row : scaled)
    for (double& v : row) v *= out.step;
  const Mat4 phi = expm(scaled);

  // Eq. 4's directional lines do not involve F, so solve G± first and then F± driven by them: one banded
  // system for all four would let partial pivoting mix the two, and the normwise-accurate answer would
  // lose the relative accuracy of a G− many orders of magnitude below F±. Unknowns z_i[c] at index 2i + c.
  // Rows: 1 surface condition, 2n continuity rows z_{i+1} − Φ z_i = forcing, 1 bottom condition; every row
  // spans at most 3 columns either side of its diagonal.
  const optics::SurfaceCoefficients& sf = in.surface;
  const optics::BottomCoefficients& bt = in.bottom;
  const int size = 2 * (n + 1), last = 2 * n;
  BandSystem g(size, 3, 3);
  // G+(0) = T_dd E_sun + R̃_dd G−(0);  G−(τ0) = R̂_dd G+(τ0)
  g.at(0, 0) = 1;
  g.at(0, 1) = -sf.rw_dd;
  g.rhs(0) = sf.t_dd * in.e_sun;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 2; ++j) {
      const int row = 1 + 2 * i + j;
      g.at(row, 2 * (i + 1) + j) = 1;
      for (int c = 0; c < 2; ++c) g.at(row, 2 * i + c) = -phi[j][c];
    }
  }
  g.at(size - 1, last + 1) = 1;
  g.at(size - 1, last) = -bt.r_dd;
  const std::vector<double> gv = g.solve();

  BandSystem f(size, 3, 3);
  // F+(0) = T_df E_sun + T_ff E_sky + R̃_df G−(0) + R̃_ff F−(0);  F−(τ0) = R̂_df G+(τ0) + R̂_ff F+(τ0)
  f.at(0, 0) = 1;
  f.at(0, 1) = -sf.rw_ff;
  f.rhs(0) = sf.t_df * in.e_sun + sf.t_ff * in.e_sky + sf.rw_df * gv[1];
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < 2; ++j) {
      const int row = 1 + 2 * i + j;
      f.at(row, 2 * (i + 1) + j) = 1;
      for (int c = 0; c < 2; ++c) f.at(row, 2 * i + c) = -phi[2 + j][2 + c];
      f.rhs(row) = phi[2 + j][0] * gv[2 * i] + phi[2 + j][1] * gv[2 * i + 1];
    }
  }
  f.at(size - 1, last + 1) = 1;
  f.at(size - 1, last) = -bt.r_ff;
  f.rhs(size - 1) = bt.r_df * gv[last];
  const std::vector<double> fv = f.solve();

  out.flow.resize(n + 1);
  for (int i = 0; i <= n; ++i) out.flow[i] = {gv[2 * i], gv[2 * i + 1], fv[2 * i], fv[2 * i + 1]};
  return out;
}
}  // namespace lagoon::test
