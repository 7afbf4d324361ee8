#include "ocean/spreading.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "ocean/spectrum.h"

namespace lagoon::ocean {
namespace {

constexpr double kMaxSwellExponent = 16.0;  // s_ξ = 16 tanh(ω_p/ω) ξ² <= 16
constexpr double kMaxBeta = 1e4;

// 48-point Gauss-Legendre rule on [-1, 1], by Newton iteration on P_48 (done once).
constexpr int kGaussPoints = 48;
struct GaussRule {
  std::array<double, kGaussPoints> x{}, w{};
};
const GaussRule& gauss_rule() {
  static const GaussRule rule = [] {
    GaussRule r;
    const int n = kGaussPoints;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
      for (int iter = 0; iter < 100; ++iter) {
        double p1 = 1.0, p0 = 0.0;
        for (int j = 1; j <= n; ++j) {
          const double pm = p0;
          p0 = p1;
          p1 = ((2.0 * j - 1.0) * z * p0 - (j - 1.0) * pm) / j;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double step = p1 / dp;
        z -= step;
        if (std::fabs(step) < 1e-16) break;
      }
      r.x[i] = z;
      r.w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    return r;
  }();
  return rule;
}

// Catmull-Rom through p0..p3 at t in [0, 1] between p1 and p2.
double catmull_rom(double p0, double p1, double p2, double p3, double t) {
  return p1 +
         0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
}

// The swell exponent axis of the tables is uniform in w = ln(s + 1/2): the normalising integrals are
// analytic in s with a singularity at s = -1/2 (from θ = ±π), so a uniform s grid would be too coarse near 0.
constexpr double kSwellOffset = 0.5;
double swell_axis(double s) {
  return std::log(s + kSwellOffset);
}

// Values on a uniform nu x ns grid over [u0, u1] x [w(0), w(16)], interpolated bicubically; points outside
// the grid are extended quadratically so the edges keep third-order accuracy.
class Table2D {
 public:
  Table2D(int nu, int ns, double u1) : nu_(nu), ns_(ns), u1_(u1), v_(static_cast<size_t>(nu) * ns) {}
  double u_at(int i) const { return u1_ * i / (nu_ - 1); }
  double s_at(int j) const {
    const double w0 = swell_axis(0.0), w1 = swell_axis(kMaxSwellExponent);
    return std::exp(w0 + (w1 - w0) * j / (ns_ - 1)) - kSwellOffset;
  }
  double& at(int i, int j) { return v_[static_cast<size_t>(i) * ns_ + j]; }
  int nu() const { return nu_; }
  int ns() const { return ns_; }

  double operator()(double u, double s) const {
    const double w0 = swell_axis(0.0), w1 = swell_axis(kMaxSwellExponent);
    const double fu = std::clamp(u / u1_, 0.0, 1.0) * (nu_ - 1);
    const double fs = std::clamp((swell_axis(s) - w0) / (w1 - w0), 0.0, 1.0) * (ns_ - 1);
    const int i = std::min(static_cast<int>(fu), nu_ - 2), j = std::min(static_cast<int>(fs), ns_ - 2);
    double rows[4];
    for (int a = 0; a < 4; ++a)
      rows[a] = catmull_rom(get(i - 1 + a, j - 1), get(i - 1 + a, j), get(i - 1 + a, j + 1),
                            get(i - 1 + a, j + 2), fs - j);
    return catmull_rom(rows[0], rows[1], rows[2], rows[3], fu - i);
  }

 private:
  double raw(int i, int j) const { return v_[static_cast<size_t>(i) * ns_ + j]; }
  double get_s(int i, int j) const {
    if (j < 0) return 3.0 * raw(i, 0) - 3.0 * raw(i, 1) + raw(i, 2);
    if (j >= ns_) return 3.0 * raw(i, ns_ - 1) - 3.0 * raw(i, ns_ - 2) + raw(i, ns_ - 3);
    return raw(i, j);
  }
  double get(int i, int j) const {
    if (i < 0) return 3.0 * get_s(0, j) - 3.0 * get_s(1, j) + get_s(2, j);
    if (i >= nu_) return 3.0 * get_s(nu_ - 1, j) - 3.0 * get_s(nu_ - 2, j) + get_s(nu_ - 3, j);
    return get_s(i, j);
  }
  int nu_, ns_;
  double u1_;
  std::vector<double> v_;
};

// Donelan-Banner with swell: R(u, s) = ∫ sech²(βθ) cos^(2s)(θ/2) dθ / ∫ sech²(βθ) dθ, u = 1/β in [0, 2.56]
// (β >= 10^-0.4 ≈ 0.398). With v = tanh(βθ), dv = β sech²(βθ) dθ, so R is the mean of cos^(2s)(θ/2) over
// v uniform in [0, tanh(βπ)]: no narrow peak left for the quadrature to miss.
const Table2D& donelan_banner_swell_table() {
  static const Table2D table = [] {
    Table2D t(97, 33, 2.56);
    const GaussRule& g = gauss_rule();
    std::array<double, kGaussPoints> log_c{};
    for (int i = 0; i < t.nu(); ++i) {
      const double u = t.u_at(i);
      const double beta = u > 0.0 ? 1.0 / u : 0.0, top = u > 0.0 ? std::tanh(std::numbers::pi / u) : 1.0;
      for (int n = 0; n < kGaussPoints; ++n) {
        const double theta = u > 0.0 ? std::atanh(0.5 * top * (g.x[n] + 1.0)) / beta : 0.0;
        log_c[n] = 2.0 * std::log(std::cos(0.5 * std::min(theta, std::numbers::pi)));
      }
      for (int j = 0; j < t.ns(); ++j) {
        double sum = 0.0;
        for (int n = 0; n < kGaussPoints; ++n) sum += 0.5 * g.w[n] * std::exp(t.s_at(j) * log_c[n]);
        t.at(i, j) = sum;
      }
    }
    return t;
  }();
  return table;
}

// Cos2 with swell: R(s) = ∫_{-π/2}^{π/2} (2/π) cos²θ cos^(2s)(θ/2) dθ, smooth (cos(θ/2) >= 1/√2 there).
// Stored as a 4 x 65 table with identical rows so it can reuse Table2D.
const Table2D& cos2_swell_table() {
  static const Table2D table = [] {
    Table2D t(4, 65, 1.0);
    const GaussRule& g = gauss_rule();
    for (int j = 0; j < t.ns(); ++j) {
      double sum = 0.0;
      for (int n = 0; n < kGaussPoints; ++n) {
        const double theta =
            0.25 * std::numbers::pi * (g.x[n] + 1.0);  // [0, π/2], doubled for the even integrand
        const double c = std::cos(theta);
        sum += 0.25 * std::numbers::pi * g.w[n] * 2.0 * (2.0 / std::numbers::pi) * c * c *
               std::pow(std::cos(0.5 * theta), 2.0 * t.s_at(j));
      }
      for (int i = 0; i < t.nu(); ++i) t.at(i, j) = sum;
    }
    return t;
  }();
  return table;
}

// sech²(x) without overflow for large |x|.
double sech2(double x) {
  const double e = std::exp(-2.0 * std::fabs(x));
  return 4.0 * e / ((1.0 + e) * (1.0 + e));
}

}  // namespace

SpreadingModel spreading_for(const SpectrumParams& spectrum) {
  SpreadingModel m;
  m.type = spectrum.spreading;
  m.peak_omega = peak_omega(spectrum);
  m.s_peak = 11.5 * std::pow(m.peak_omega * spectrum.wind_speed_mps / kGravity, -2.5);  // U/c_p = ω_p U/g
  m.swell = spectrum.swell;
  return m;
}

double cos2s_exponent(const SpreadingModel& model, double omega) {
  if (!(omega > 0.0)) return 0.0;
  const double r = omega / model.peak_omega;
  return r <= 1.0 ? model.s_peak * std::pow(r, 5.0) : model.s_peak * std::pow(r, -2.5);
}

double swell_exponent(double omega, double peak_omega, double swell) {
  if (!(omega > 0.0) || swell == 0.0) return 0.0;
  return 16.0 * std::tanh(peak_omega / omega) * swell * swell;
}

double cos2s_normalisation(double s) {
  // Q(s) = Γ(s+1)/(2√π Γ(s+1/2)) by Legendre's duplication formula; lgamma keeps large s finite.
  return std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(std::numbers::pi));
}

double donelan_banner_beta(double r) {
  if (!(r > 0.0)) return kMaxBeta;
  double beta;
  if (r > 0.56 && r < 0.95) {
    beta = 2.61 * std::pow(r, 1.3);
  } else if (r >= 0.95 && r < 1.6) {
    beta = 2.28 * std::pow(r, -1.3);
  } else {
    const double epsilon = -0.4 + 0.8393 * std::exp(-0.567 * std::log(r * r));
    beta = std::pow(10.0, std::min(epsilon, 4.0));
  }
  return std::min(beta, kMaxBeta);
}

double spreading(const SpreadingModel& model, double omega, double theta) {
  if (!(omega > 0.0)) return 1.0 / (2.0 * std::numbers::pi);
  theta = std::remainder(theta, 2.0 * std::numbers::pi);  // (-π, π]
  const double s_swell = swell_exponent(omega, model.peak_omega, model.swell);
  const double half_cos = std::fabs(std::cos(0.5 * theta));
  switch (model.type) {
    case Spreading::Cos2s: {
      const double s = cos2s_exponent(model, omega) + s_swell;
      return cos2s_normalisation(s) * std::pow(half_cos, 2.0 * s);
    }
    case Spreading::Cos2: {
      if (std::fabs(theta) >= 0.5 * std::numbers::pi) return 0.0;
      const double c = std::cos(theta);
      const double d = (2.0 / std::numbers::pi) * c * c;
      if (s_swell == 0.0) return d;
      return d * std::pow(half_cos, 2.0 * s_swell) / cos2_swell_table()(0.0, s_swell);
    }
    case Spreading::DonelanBanner: {
      const double beta = donelan_banner_beta(omega / model.peak_omega);
      const double d = beta / (2.0 * std::tanh(beta * std::numbers::pi)) * sech2(beta * theta);
      if (s_swell == 0.0) return d;
      return d * std::pow(half_cos, 2.0 * s_swell) / donelan_banner_swell_table()(1.0 / beta, s_swell);
    }
  }
  return 1.0 / (2.0 * std::numbers::pi);
}

double spreading(const SpectrumParams& spectrum, double omega, double theta) {
  return spreading(spreading_for(spectrum), omega, theta);
}

}  // namespace lagoon::ocean
