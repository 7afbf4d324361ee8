// Closed-form solution of the four-flow equations (seed eq. 4) with boundary conditions (seed eq. 7),
// derived here from scratch; the seed's printed eqs. 5, 8 and 9 contain errors (noted below).
//
// 1. Directional flows. λ = k + S1 + S2 = (χ + σ)/ε = 1, so G+ = g0 e^{−τ}, G− = gh e^{−(τ0−τ)}.
//    Eq. 7 lines 1 and 3, with D = e^{−τ0}: g0 = T_dd E_sun / (1 − R̃_dd R̂_dd D²), gh = R̂_dd D g0.
//    (The seed's eq. 8 is this only with D = e^{+λτ0}, not its printed e^{−λτ0}.)
// 2. Diffuse modes. F = (F+, F−) obeys F' = M F + G+ (S1, −S2) + G− (S2, −S1), M = [[−(k+S), S], [−S, k+S]].
//    M has eigenvalues ∓λ0, λ0² = (k+S)² − S² = k(k+2S), with eigenvectors v− = (1, A3) (decays downwards)
//    and v+ = (A3, 1) (decays upwards), A3 = S/(k+S+λ0) = (k+2S−λ0)/(k+2S+λ0). The seed's eq. 5 prints the
//    C3 mode with e^{−λ0τ}; it is e^{+λ0τ}, written here e^{−λ0(τ0−τ)}, normalised by F− (its A4 = 1/A3
//    normalisation by F+ is singular at S = 0).
// 3. Forcing in the mode basis: (S1, −S2) = a v− + b v+, a = (S1 + A3 S2)/(1 − A3²), b = −(S2 + A3 S1)/(1 −
// A3²),
//    and by the up/down symmetry (S2, −S1) = −b v− − a v+. The v− coordinate obeys c−' = −λ0 c− + a g0
//    e^{−τ}, which resonates as λ0 → 1 (σ → 0): the seed's A1, A2 ∝ 1/(λ0² − λ²) blow up. Instead take the
//    particular solution vanishing at τ = 0, c− = a g0 Δ(τ), Δ(t) = (e^{−λ0 t} − e^{−t})/(1 − λ0) → t e^{−t}.
//    The v+ coordinate, c+' = λ0 c+ + b g0 e^{−τ}, gives c+ = q g0 e^{−τ} with q = −b/(1 + λ0). G− mirrors
//    this: c+ = a gh Δ(τ0−τ), c− = q gh e^{−(τ0−τ)}. With p = a, S1 = σ'(1+X1)/2, S2 = σ'(1−X1)/2, σ' = σ/ε:
//      p = σ'/2 [1/(1−A3) + X1/(1+A3)],   q = σ'/2 [1/(1−A3) − X1/(1+A3)] / (1 + λ0).
// 4. General solution, u and w the free downward and upward modes:
//    F+ = g0 [p Δ(τ) + q A3 e^{−τ}] + gh [p A3 Δ(τ0−τ) + q e^{−(τ0−τ)}] + u e^{−λ0τ} + w A3 e^{−λ0(τ0−τ)}
//    F− = g0 [p A3 Δ(τ) + q e^{−τ}] + gh [p Δ(τ0−τ) + q A3 e^{−(τ0−τ)}] + u A3 e^{−λ0τ} + w e^{−λ0(τ0−τ)}
//    Every exponential decays from the boundary it is referred to, so nothing overflows for any τ0.
// 5. Eq. 7 lines 2 and 4, L = e^{−λ0τ0}, P0, M0, Ph, Mh = the g0/gh parts of F+(0), F−(0), F+(τ0), F−(τ0):
//      (1 − R̃_ff A3) u + L (A3 − R̃_ff) w = T_df E_sun + T_ff E_sky + R̃_df gh D + R̃_ff M0 − P0
//      L (A3 − R̂_ff) u + (1 − R̂_ff A3) w = R̂_df g0 D + R̂_ff Ph − Mh
//    (The seed's eq. 9 does not follow from its eqs. 5 and 7: it swaps A2/A3/A4 and the D0 scaling.)
// 6. A diffuse path-length factor D (FourFlowInput::diffuse_path_factor) scales the diffuse rows' own terms:
//    F' = D M F + (forcing as above). D M has the same eigenvectors (A3 unchanged) and eigenvalues ∓Dλ0, so
//    every λ0 above that is a decay rate (Δ, q's 1 + λ0, the free modes, L) becomes Λ = Dλ0; p stays a.
//    With x = 1 − R A3, y = A3 − R: x² − y² = (1 − A3²)(1 − R²) >= 0, so ρ = y/x is in [−1, 1] and the
//    scaled determinant 1 − L² ρ1 ρ2 vanishes only for a lossless cavity (τ0 = 0, R = 1 at both ends).
#include "optics/four_flow.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lagoon::optics {
namespace {

Result<void> check(bool ok, const std::string& what) {
  if (ok) return {};
  return make_error("four-flow model: " + what);
}

bool unit_interval(double v) {
  return std::isfinite(v) && v >= 0.0 && v <= 1.0;
}

Result<void> validate(const FourFlowInput& in) {
  const SurfaceCoefficients& s = in.surface;
  const BottomCoefficients& b = in.bottom;
  for (const Result<void>& r : {
           check(std::isfinite(in.absorption_per_m) && in.absorption_per_m > 0,
                 "absorption_per_m (χ) must be finite and > 0"),
           check(std::isfinite(in.scattering_per_m) && in.scattering_per_m >= 0,
                 "scattering_per_m (σ) must be finite and >= 0"),
           check(std::isfinite(in.phase_x1) && in.phase_x1 >= 0 && in.phase_x1 < 3,
                 "phase_x1 (X1) must be in [0, 3)"),
           check(std::isfinite(in.depth_m) && in.depth_m >= 0, "depth_m (h) must be finite and >= 0"),
           check(unit_interval(s.t_dd) && unit_interval(s.r_dd) && unit_interval(s.t_df) &&
                     unit_interval(s.r_df) && unit_interval(s.t_ff) && unit_interval(s.r_ff) &&
                     unit_interval(s.rw_dd) && unit_interval(s.rw_df) && unit_interval(s.rw_ff) &&
                     unit_interval(s.tw_ff),
                 "surface coefficients must be in [0, 1]"),
           check(unit_interval(b.r_dd) && unit_interval(b.r_df) && unit_interval(b.r_ff),
                 "bottom coefficients must be in [0, 1]"),
           check(std::isfinite(in.e_sun) && in.e_sun >= 0, "e_sun must be finite and >= 0"),
           check(std::isfinite(in.e_sky) && in.e_sky >= 0, "e_sky must be finite and >= 0"),
           check(std::isfinite(in.diffuse_path_factor) && in.diffuse_path_factor >= 1 &&
                     in.diffuse_path_factor <= 4,
                 "diffuse_path_factor (D) must be in [1, 4]"),
       }) {
    if (!r) return r;
  }
  // For X1 > 2 the seed's diffuse backscatter S = σ(1 − X1/2)/ε is negative; once k + 2S <= 0, λ0² <= 0 and
  // the diffuse flows oscillate with depth without decaying, and the boundary-value problem is singular at
  // a sequence of depths. That is the phase-function truncation failing, not a physical water.
  return check(in.absorption_per_m + in.scattering_per_m * (2.0 - in.phase_x1) > 0,
               "phase_x1 (X1) = " + std::to_string(in.phase_x1) +
                   " is too large for σ/χ = " + std::to_string(in.scattering_per_m / in.absorption_per_m) +
                   ": the model needs χ + σ(2 − X1) > 0 (its diffuse backscatter S = σ(1 − X1/2) turns "
                   "negative); reduce X1, e.g. by delta-Eddington scaling of the phase function");
}

// 1 − |ρ| for ρ = y/x, y = A3 − R, x = 1 − R A3, without forming the difference.
double one_minus_abs_rho(double a3, double r, double x) {
  return (a3 >= r ? (1.0 - a3) * (1.0 + r) : (1.0 + a3) * (1.0 - r)) / x;
}

struct FreeModes {
  double u, w;  // down from the surface, up from the bottom
};

// Step 5's 2x2 system for the free modes, row-normalised: u + L ρ1 w = r1/x1, L ρ2 u + w = r2/x2, with
// L = e^{−Λτ0}. `r_*_ff` are the diffuse reflectances seen from the water at each end, `rhs_*` the right
// sides r1, r2. Its determinant is formed from non-negative terms where cancellation could lose it.
Result<FreeModes> solve_free_modes(double a3, double decay, double tau0, double r_top_ff, double rhs_top,
                                   double r_bottom_ff, double rhs_bottom) {
  const double l = std::exp(-decay * tau0);
  const double x_top = 1.0 - r_top_ff * a3, x_bottom = 1.0 - r_bottom_ff * a3;
  const double rho_top = (a3 - r_top_ff) / x_top, rho_bottom = (a3 - r_bottom_ff) / x_bottom;
  double det;
  if (rho_top * rho_bottom <= 0) {
    det = 1.0 - l * l * rho_top * rho_bottom;
  } else {
    // 1 − L² ρ1ρ2 = (1 − L²) + L² [(1 − |ρ1|) + |ρ1| (1 − |ρ2|)]: a sum of non-negative terms.
    const double m_top = one_minus_abs_rho(a3, r_top_ff, x_top);
    const double m_bottom = one_minus_abs_rho(a3, r_bottom_ff, x_bottom);
    det = -std::expm1(-2.0 * decay * tau0) + l * l * (m_top + std::fabs(rho_top) * m_bottom);
  }
  if (!(det > 0))
    return make_error("four-flow model: lossless cavity (depth 0 between mirrors), no solution");
  const double c_top = rhs_top / x_top, c_bottom = rhs_bottom / x_bottom;
  return FreeModes{(c_top - l * rho_top * c_bottom) / det, (c_bottom - l * rho_bottom * c_top) / det};
}

}  // namespace

double FourFlowSolution::clamp_tau(double tau) const {
  return std::clamp(tau, 0.0, tau0);
}

double FourFlowSolution::non_negative(double flow) const {
  return clamp_negative_ ? std::max(flow, 0.0) : flow;
}

double FourFlowSolution::decay_difference(double t) const {
  // e^{−min(1, Λ) t} t (1 − e^{−|δ|t})/(|δ|t), δ = 1 − Λ: expm1 keeps it exact as δ → 0, and the slower of
  // the two exponentials is factored out so nothing overflows when Λ > 1 (D > 1).
  const double x = std::fabs(one_minus_decay_) * t;
  const double ratio = x > 0.0 ? -std::expm1(-x) / x : 1.0;
  return std::exp(-std::min(1.0, lambda_diffuse) * t) * t * ratio;
}

double FourFlowSolution::g_plus(double tau) const {
  return g0_ * std::exp(-clamp_tau(tau));
}

double FourFlowSolution::g_minus(double tau) const {
  return gh_ * std::exp(-(tau0 - clamp_tau(tau)));
}

double FourFlowSolution::f_plus(double tau) const {
  const double t = clamp_tau(tau), up = tau0 - t;
  return non_negative(g0_ * (p_ * decay_difference(t) + q_ * a3 * std::exp(-t)) +
                      gh_ * (p_ * a3 * decay_difference(up) + q_ * std::exp(-up)) +
                      u_ * std::exp(-lambda_diffuse * t) + w_ * a3 * std::exp(-lambda_diffuse * up));
}

double FourFlowSolution::f_minus(double tau) const {
  const double t = clamp_tau(tau), up = tau0 - t;
  return non_negative(g0_ * (p_ * a3 * decay_difference(t) + q_ * std::exp(-t)) +
                      gh_ * (p_ * decay_difference(up) + q_ * a3 * std::exp(-up)) +
                      u_ * a3 * std::exp(-lambda_diffuse * t) + w_ * std::exp(-lambda_diffuse * up));
}

Result<FourFlowSolution> solve_four_flow(const FourFlowInput& in) {
  if (Result<void> ok = validate(in); !ok) return ok.error();
  const double chi = in.absorption_per_m, sigma = in.scattering_per_m, x1 = in.phase_x1;
  const double eps = chi + sigma;
  const double sp = sigma / eps;  // σ' = S1 + S2
  FourFlowSolution f;
  f.k = chi / eps;
  f.s = 0.5 * sp * (2.0 - x1);
  f.s1 = 0.5 * sp * (1.0 + x1);
  f.s2 = 0.5 * sp * (1.0 - x1);
  f.lambda = 1.0;
  f.tau0 = eps * in.depth_m;
  f.clamp_negative_ = x1 <= 1.0;

  // k + 2S and k + S straight from χ, σ (S may be negative: avoid subtracting it from k).
  const double k2s = (chi + sigma * (2.0 - x1)) / eps;
  const double ks = f.s >= 0 ? f.k + f.s : k2s - f.s;
  f.lambda0 = std::sqrt(f.k * k2s);
  f.diffuse_path = in.diffuse_path_factor;
  f.lambda_diffuse = f.diffuse_path * f.lambda0;
  f.one_minus_decay_ =
      f.diffuse_path == 1.0
          ? sp * (f.k * x1 + sp) / (1.0 + f.lambda0)  // (1 − λ0²)/(1 + λ0), 1 − λ0² = σ'(kX1 + σ')
          : 1.0 - f.lambda_diffuse;
  const double denom = ks + f.lambda0;
  f.a3 = f.s / denom;
  const double one_minus_a3 = (f.k + f.lambda0) / denom, one_plus_a3 = (k2s + f.lambda0) / denom;
  f.p_ = 0.5 * sp * (1.0 / one_minus_a3 + x1 / one_plus_a3);
  f.q_ = 0.5 * sp * (1.0 / one_minus_a3 - x1 / one_plus_a3) / (1.0 + f.lambda_diffuse);

  const SurfaceCoefficients& s = in.surface;
  const BottomCoefficients& b = in.bottom;
  const double d = std::exp(-f.tau0);
  const double mirror = 1.0 - s.rw_dd * b.r_dd * d * d;
  if (!(mirror > 0))
    return make_error("four-flow model: lossless cavity (depth 0 between mirrors), no solution");
  f.g0_ = s.t_dd * in.e_sun / mirror;
  f.gh_ = b.r_dd * d * f.g0_;

  // The forced (g0, gh) parts of F+ and F− at both boundaries.
  const double a3 = f.a3, p = f.p_, q = f.q_, dd0 = f.decay_difference(f.tau0);
  const double p0 = f.g0_ * q * a3 + f.gh_ * (p * a3 * dd0 + q * d);
  const double m0 = f.g0_ * q + f.gh_ * (p * dd0 + q * a3 * d);
  const double ph = f.g0_ * (p * dd0 + q * a3 * d) + f.gh_ * q;
  const double mh = f.g0_ * (p * a3 * dd0 + q * d) + f.gh_ * q * a3;
  const double r1 = s.t_df * in.e_sun + s.t_ff * in.e_sky + s.rw_df * f.gh_ * d + s.rw_ff * m0 - p0;
  const double r2 = b.r_df * f.g0_ * d + b.r_ff * ph - mh;

  Result<FreeModes> modes = solve_free_modes(a3, f.lambda_diffuse, f.tau0, s.rw_ff, r1, b.r_ff, r2);
  if (!modes) return modes.error();
  f.u_ = modes->u;
  f.w_ = modes->w;
  if (!std::isfinite(f.u_) || !std::isfinite(f.w_) || !std::isfinite(f.g0_)) {
    return make_error("four-flow model: non-finite solution (inputs too extreme)");
  }
  return f;
}

}  // namespace lagoon::optics
