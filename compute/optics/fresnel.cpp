#include "optics/fresnel.h"

#include <array>
#include <cmath>
#include <numbers>

namespace lagoon::optics {
namespace {

// sin² of the transmitted angle; >= 1 means total internal reflection. (1 − c)(1 + c) keeps the precision
// of sin² near normal incidence.
double sin2_transmitted(double n_from, double n_to, double cos_i) {
  const double eta = n_from / n_to;
  return eta * eta * (1.0 - cos_i) * (1.0 + cos_i);
}

double clamp_cos(double c) {
  return std::fmin(std::fabs(c), 1.0);
}

// Gauss–Legendre nodes and weights on [0, 1]. The integrand of fresnel_hemispherical (below) is analytic
// on the closed interval, so 48 points reach double precision.
constexpr int kQuadraturePoints = 48;
struct Quadrature {
  std::array<double, kQuadraturePoints> x, w;
};

Quadrature gauss_legendre_unit() {
  Quadrature q{};
  constexpr int n = kQuadraturePoints;
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from the Chebyshev-like first guess; converges in a few steps for every root.
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = z;
      for (int j = 2; j <= n; ++j) {
        const double p2 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    q.x[i] = 0.5 * (1.0 - z);
    q.w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // half of the [-1, 1] weight 2/((1 − z²) P_n'²)
  }
  return q;
}

}  // namespace

double fresnel_reflectance(double n_from, double n_to, double cos_incidence) {
  const double ci = clamp_cos(cos_incidence);
  const double sin2_t = sin2_transmitted(n_from, n_to, ci);
  if (sin2_t >= 1.0) return 1.0;
  const double ct = std::sqrt(1.0 - sin2_t);
  const double rs = (n_from * ci - n_to * ct) / (n_from * ci + n_to * ct);
  const double rp = (n_to * ci - n_from * ct) / (n_to * ci + n_from * ct);
  return 0.5 * (rs * rs + rp * rp);
}

double refracted_cos(double n_from, double n_to, double cos_incidence) {
  const double sin2_t = sin2_transmitted(n_from, n_to, clamp_cos(cos_incidence));
  return sin2_t >= 1.0 ? 0.0 : std::sqrt(1.0 - sin2_t);
}

double fresnel_hemispherical(double n_from, double n_to) {
  if (n_from == n_to) return 0.0;
  if (n_from > n_to) {
    // From the dense side the integrand has a kink at the critical angle, so do not integrate it. Every
    // direction beyond the critical cosine μc is totally reflected: that is μc² = 1 − (n_to/n_from)² of the
    // flux. The rest maps one-to-one (Snell) onto the other side's hemisphere with μ dμ = μt dμt
    // (n_to/n_from)², and R is the same both ways along a ray (reciprocity), so that part is (n_to/n_from)²
    // R̄(n_to → n_from).
    const double m2 = (n_to / n_from) * (n_to / n_from);
    return 1.0 - m2 * (1.0 - fresnel_hemispherical(n_to, n_from));
  }
  static const Quadrature q = gauss_legendre_unit();
  double sum = 0;
  for (int i = 0; i < kQuadraturePoints; ++i)
    sum += q.w[i] * fresnel_reflectance(n_from, n_to, q.x[i]) * 2.0 * q.x[i];
  return sum;
}

}  // namespace lagoon::optics
