#include "optics/sky_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/cie.h"
#include "optics/csv_table.h"

namespace lagoon::optics {
namespace {

// The grid the per-wavelength scale is computed on; fine enough that coarser images agree within 0.1 %.
constexpr int kNormalisationTheta = 64;
constexpr int kShiftGrid = 24;  // the colour shift's grid: the chromaticity converges long before the scale

// Preetham et al. (1999) Appendix A.2: the Perez coefficients are linear in T, (slope, intercept).
struct Linear {
  double slope, intercept;
  double at(double t) const { return slope * t + intercept; }
};
constexpr Linear kPerezLum[5] = {
    {0.1787, -1.4630}, {-0.3554, 0.4275}, {-0.0227, 5.3251}, {0.1206, -2.5771}, {-0.0670, 0.3703}};
constexpr Linear kPerezX[5] = {
    {-0.0193, -0.2592}, {-0.0665, 0.0008}, {-0.0004, 0.2125}, {-0.0641, -0.8989}, {-0.0033, 0.0452}};
constexpr Linear kPerezY[5] = {
    {-0.0167, -0.2608}, {-0.0950, 0.0092}, {-0.0079, 0.2102}, {-0.0441, -1.6537}, {-0.0109, 0.0529}};
// Zenith chromaticity: (T², T, 1) · R · (θ_s³, θ_s², θ_s, 1)ᵀ, θ_s the sun's zenith angle in radians.
constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

double zenith_chromaticity(const double (&r)[3][4], double t, double theta_s) {
  const double tv[3] = {t * t, t, 1.0};
  const double sv[4] = {theta_s * theta_s * theta_s, theta_s * theta_s, theta_s, 1.0};
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) sum += tv[i] * r[i][j] * sv[j];
  return sum;
}

glm::vec4 perez_abcd(const Linear (&c)[5], double t) {
  return glm::vec4(float(c[0].at(t)), float(c[1].at(t)), float(c[2].at(t)), float(c[3].at(t)));
}

DaylightBasis load_basis() {
  const CsvTable table = embedded_table_or_abort("cie_daylight_basis_10nm.csv");
  const std::vector<double> nm = numbers_or_abort(table, "wavelength_nm");
  const char* columns[3] = {"s0", "s1", "s2"};
  DaylightBasis basis;
  for (int k = 0; k < 3; ++k) {
    const std::vector<double> v = numbers_or_abort(table, columns[k]);
    for (int i = 0; i < kSamples; ++i) {
      const double at = wavelength_nm(i);
      const auto hi = std::lower_bound(nm.begin(), nm.end(), at);
      if (hi == nm.end())
        abort_table_defect(table.source() + ": does not reach " + std::to_string(at) + " nm");
      const std::size_t j = std::size_t(hi - nm.begin());
      if (*hi == at) {
        basis.s[k][i] = v[j];
        continue;
      }
      if (j == 0) abort_table_defect(table.source() + ": starts after " + std::to_string(at) + " nm");
      const double f = (at - nm[j - 1]) / (nm[j] - nm[j - 1]);
      basis.s[k][i] = v[j - 1] + f * (v[j] - v[j - 1]);
    }
  }
  return basis;
}

double y_integral(const Spectrum& s) {
  return spectrum_to_xyz(s).y;
}

}  // namespace

const DaylightBasis& daylight_basis() {
  static const DaylightBasis basis = load_basis();
  return basis;
}

Spectrum daylight_spectrum(double x, double y) {
  const double den = 0.0241 + 0.2562 * x - 0.7341 * y;
  const double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / den;
  const double m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / den;
  const DaylightBasis& b = daylight_basis();
  Spectrum s{};
  for (int i = 0; i < kSamples; ++i) s[i] = b.s[0][i] + m1 * b.s[1][i] + m2 * b.s[2][i];
  return s;
}

double sky_turbidity(const SkyParams& params) {
  const double um = 0.55;
  const double tau_r =
      (params.surface_pressure_hpa / 1013.25) / (std::pow(um, 4) * (115.6406 - 1.335 / (um * um)));
  const double tau_a = params.aerosol_optical_depth_500nm * std::pow(um / 0.5, -params.angstrom_alpha);
  return (tau_r + tau_a) / tau_r;
}

namespace {

// Preetham's coefficients at turbidity t for the sun at zenith angle theta_s; Y_k in basis*.w.
gpu::SkyModelGpu preetham_shape(double t, double theta_s) {
  gpu::SkyModelGpu m{};
  m.perez_lum = perez_abcd(kPerezLum, t);
  m.perez_x = perez_abcd(kPerezX, t);
  m.perez_y = perez_abcd(kPerezY, t);
  m.perez_e = glm::vec4(float(kPerezLum[4].at(t)), float(kPerezX[4].at(t)), float(kPerezY[4].at(t)), 0);
  const float cos_s = float(std::cos(theta_s)), gamma_zenith = float(theta_s);
  const float fx0 = gpu::sky_perez(m.perez_x, m.perez_e.y, 1.0f, gamma_zenith, cos_s);
  const float fy0 = gpu::sky_perez(m.perez_y, m.perez_e.z, 1.0f, gamma_zenith, cos_s);
  m.zenith = glm::vec4(float(zenith_chromaticity(kZenithX, t, theta_s)) / fx0,
                       float(zenith_chromaticity(kZenithY, t, theta_s)) / fy0, 0, 0);
  const DaylightBasis& basis = daylight_basis();
  m.basis0.w = float(y_integral(basis.s[0]));
  m.basis1.w = float(y_integral(basis.s[1]));
  m.basis2.w = float(y_integral(basis.s[2]));
  return m;
}

// A_k = ∫ w_k cos θ dω over the sky on an n × 2n (θ, φ) grid: the unscaled sky's irradiance is Σ A_k S_k(λ).
// Calls f(direction, cos θ dω) for the cells of the upper hemisphere split by the midpoint rule into an
// n × 2n grid of (θ, φ); ∑ f's weights is π.
template <typename F>
void for_each_sky_cell(int n, F&& f) {
  const double d_theta = (std::numbers::pi / 2) / n, d_phi = 2 * std::numbers::pi / (2 * n);
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * d_theta;
    const double weight = std::cos(theta) * std::sin(theta) * d_theta * d_phi;
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = (j + 0.5) * d_phi;
      f(glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)),
        weight);
    }
  }
}

glm::dvec3 hemisphere_weights(const gpu::SkyModelGpu& m, glm::vec3 sun, int n) {
  glm::dvec3 a(0.0);
  for_each_sky_cell(n, [&](glm::dvec3 dir, double weight) {
    a += glm::dvec3(gpu::sky_daylight_weights(m, glm::vec3(dir), sun)) * weight;
  });
  return a;
}

glm::dvec2 weights_chromaticity(glm::dvec3 a) {
  const DaylightBasis& b = daylight_basis();
  return chromaticity(a.x * spectrum_to_xyz(b.s[0]) + a.y * spectrum_to_xyz(b.s[1]) +
                      a.z * spectrum_to_xyz(b.s[2]));
}

glm::vec3 sun_at(double theta_s) {
  return glm::vec3(float(std::sin(theta_s)), float(std::cos(theta_s)), 0.0f);
}

}  // namespace

SkyRadiance::SkyRadiance(double sun_elevation_deg, const SkyParams& params) {
  const double elevation = std::clamp(sun_elevation_deg, 1.0, 90.0);
  const double theta_s = (90.0 - elevation) * std::numbers::pi / 180.0;
  sun_ = glm::dvec3(sun_at(theta_s));
  irradiance_ = clear_sky(elevation, params);
  turbidity_ = std::clamp(sky_turbidity(params), 2.0, 10.0);
  model_ = preetham_shape(turbidity_, theta_s);
  // Shift Preetham's chromaticities so the colour of their sky irradiance is Bird's E_sky's; the shift runs
  // along the daylight locus, so every direction keeps a daylight colour (a fixed point: 4 steps reach 1e-4).
  const glm::dvec2 target = chromaticity(spectrum_to_xyz(irradiance_.sky));
  for (int step = 0; step < 4; ++step) {
    const glm::dvec2 now = weights_chromaticity(hemisphere_weights(model_, glm::vec3(sun_), kShiftGrid));
    model_.zenith.z += float(target.x - now.x);
    model_.zenith.w += float(target.y - now.y);
  }
  // N(λ) = Σ A_k S_k(λ) is the unscaled sky's irradiance; B_k = E_sky S_k / N.
  const glm::dvec3 a = hemisphere_weights(model_, glm::vec3(sun_), kNormalisationTheta);
  const DaylightBasis& basis = daylight_basis();
  for (int i = 0; i < kSamples; ++i) {
    const double norm = a.x * basis.s[0][i] + a.y * basis.s[1][i] + a.z * basis.s[2][i];
    scale_[i] = norm > 0 ? irradiance_.sky[i] / norm : 0.0;
    for (int k = 0; k < 3; ++k) basis_[k][i] = scale_[i] * basis.s[k][i];
  }
}

glm::dvec3 SkyRadiance::weights(glm::dvec3 dir) const {
  return glm::dvec3(gpu::sky_daylight_weights(model_, glm::vec3(dir), glm::vec3(sun_)));
}

Spectrum SkyRadiance::radiance(glm::dvec3 dir) const {
  const glm::dvec3 w = weights(dir);
  Spectrum l{};
  for (int i = 0; i < kSamples; ++i) l[i] = w.x * basis_[0][i] + w.y * basis_[1][i] + w.z * basis_[2][i];
  return l;
}

Spectrum sky_image_irradiance(const SkyRadiance& sky, int n_theta) {
  Spectrum e{};
  for_each_sky_cell(n_theta, [&](glm::dvec3 dir, double weight) {
    const Spectrum l = sky.radiance(dir);
    for (int k = 0; k < kSamples; ++k) e[k] += l[k] * weight;
  });
  return e;
}

}  // namespace lagoon::optics
