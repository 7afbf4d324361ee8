#include "optics/rough_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "optics/fresnel.h"

namespace lagoon::optics {
namespace {

constexpr double kAir = 1.0;

// A quadrature of the upper hemisphere, cosine-free: directions and solid-angle weights (Gauss-Legendre in
// cos θ, uniform in φ).
struct Hemisphere {
  std::vector<glm::dvec3> directions;
  std::vector<double> weights;
};

const Hemisphere& hemisphere() {
  static const Hemisphere h = [] {
    // 16-point Gauss-Legendre on [-1, 1].
    static constexpr std::array<double, 8> x{0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                             0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                             0.9445750230732326, 0.9894009349916499};
    static constexpr std::array<double, 8> w{0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                             0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                             0.0622535239386479, 0.0271524594117541};
    Hemisphere out;
    constexpr int kPhi = 32;
    for (int i = 0; i < 16; ++i) {
      const double xi = i < 8 ? -x[7 - i] : x[i - 8], wi = i < 8 ? w[7 - i] : w[i - 8];
      const double mu = 0.5 * (xi + 1), weight_mu = 0.5 * wi;  // on [0, 1]
      const double sin_theta = std::sqrt(1 - mu * mu);
      for (int j = 0; j < kPhi; ++j) {
        const double phi = 2 * std::numbers::pi * (j + 0.5) / kPhi;
        out.directions.push_back({sin_theta * std::cos(phi), mu, sin_theta * std::sin(phi)});
        out.weights.push_back(weight_mu * 2 * std::numbers::pi / kPhi);
      }
    }
    return out;
  }();
  return h;
}

// Sums of weight and weight × reflectance over facets, per coefficient.
struct Accumulated {
  double sun_w = 0, sun_r = 0, sky_w = 0, sky_r = 0, up_w = 0, up_r = 0;

  // One facet of slope s and probability (or count) `p`. A facet of normal n intercepts light from ω in
  // proportion to max(ω·n, 0) / n_y per unit of horizontal area (its area is 1/n_y of its footprint).
  void add(double ior, glm::dvec3 sun, glm::dvec2 s, double p) {
    const glm::dvec3 n = glm::dvec3(-s.x, 1.0, -s.y) / std::sqrt(1 + s.x * s.x + s.y * s.y);
    const double share = p / n.y;
    const double cs = glm::dot(sun, n);
    if (cs > 0) {
      sun_w += share * cs;
      sun_r += share * cs * fresnel_reflectance(kAir, ior, cs);
    }
    const Hemisphere& h = hemisphere();
    for (size_t i = 0; i < h.directions.size(); ++i) {
      // Sky light arrives from ω (upper hemisphere); upwelling light under the surface travels toward ω.
      const double c = glm::dot(h.directions[i], n);
      if (c <= 0) continue;
      const double w = share * h.weights[i] * c;
      sky_w += w;
      sky_r += w * fresnel_reflectance(kAir, ior, c);
      up_w += w;
      up_r += w * fresnel_reflectance(ior, kAir, c);
    }
  }

  SurfaceCoefficients finish(double ior, glm::dvec3 sun) const {
    SurfaceCoefficients c = surface_coefficients(ior, std::acos(std::clamp(sun.y, -1.0, 1.0)));
    if (sun.y > 0 && sun_w > 0) {
      c.r_dd = sun_r / sun_w;
      c.t_dd = 1 - c.r_dd;
      c.rw_dd = c.r_dd;
    }
    c.r_ff = sky_r / sky_w;
    c.t_ff = 1 - c.r_ff;
    c.rw_ff = up_r / up_w;
    c.tw_ff = 1 - c.rw_ff;
    return c;
  }
};

bool all_flat(std::span<const glm::dvec2> slopes) {
  for (glm::dvec2 s : slopes)
    if (s.x != 0 || s.y != 0) return false;
  return true;
}

}  // namespace

SurfaceCoefficients patch_surface_coefficients(double ior, glm::dvec3 sun,
                                               std::span<const glm::dvec2> slopes) {
  if (slopes.empty() || all_flat(slopes))
    return surface_coefficients(ior, std::acos(std::clamp(sun.y, -1.0, 1.0)));
  Accumulated a;
  for (glm::dvec2 s : slopes) a.add(ior, sun, s, 1.0);
  return a.finish(ior, sun);
}

SurfaceCoefficients gaussian_surface_coefficients(double ior, glm::dvec3 sun, const SlopeCovariance& c) {
  if (c.mean_square() <= 0) return surface_coefficients(ior, std::acos(std::clamp(sun.y, -1.0, 1.0)));
  // Principal axes of the covariance: s = u e1 sqrt(l1) + v e2 sqrt(l2), u and v standard normal.
  const double mean = 0.5 * (c.xx + c.zz),
               half = std::sqrt(0.25 * (c.xx - c.zz) * (c.xx - c.zz) + c.xz * c.xz);
  const double l1 = mean + half, l2 = std::max(mean - half, 0.0);
  const double angle = 0.5 * std::atan2(2 * c.xz, c.xx - c.zz);
  const glm::dvec2 e1(std::cos(angle), std::sin(angle)), e2(-std::sin(angle), std::cos(angle));
  // Trapezoid over ±6σ: for a smooth integrand under a Gaussian it converges exponentially.
  constexpr int kNodes = 33;
  constexpr double kSpan = 6.0, kStep = 2 * kSpan / (kNodes - 1);
  Accumulated a;
  for (int i = 0; i < kNodes; ++i)
    for (int j = 0; j < kNodes; ++j) {
      const double u = -kSpan + i * kStep, v = -kSpan + j * kStep;
      const double p = std::exp(-0.5 * (u * u + v * v));
      a.add(ior, sun, u * std::sqrt(l1) * e1 + v * std::sqrt(l2) * e2, p);
    }
  return a.finish(ior, sun);
}

SurfaceCoefficients wavy_surface_coefficients(double ior, double sun_zenith_rad, const SlopeCovariance& c) {
  if (c.mean_square() <= 0) return surface_coefficients(ior, sun_zenith_rad);
  SurfaceCoefficients sum{};
  constexpr int kAzimuths = 8;
  for (int k = 0; k < kAzimuths; ++k) {
    const double phi = 2 * std::numbers::pi * k / kAzimuths;
    const glm::dvec3 sun(std::sin(sun_zenith_rad) * std::sin(phi), std::cos(sun_zenith_rad),
                         std::sin(sun_zenith_rad) * std::cos(phi));
    const SurfaceCoefficients one = gaussian_surface_coefficients(ior, sun, c);
    for (double SurfaceCoefficients::*m :
         {&SurfaceCoefficients::t_dd, &SurfaceCoefficients::r_dd, &SurfaceCoefficients::t_df,
          &SurfaceCoefficients::r_df, &SurfaceCoefficients::t_ff, &SurfaceCoefficients::r_ff,
          &SurfaceCoefficients::rw_dd, &SurfaceCoefficients::rw_df, &SurfaceCoefficients::rw_ff,
          &SurfaceCoefficients::tw_ff})
      sum.*m += one.*m / kAzimuths;
  }
  return sum;
}

}  // namespace lagoon::optics
