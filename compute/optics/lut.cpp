#include "optics/lut.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "optics/colour.h"
#include "optics/four_flow.h"
#include "optics/surface.h"
#include "optics/water_types.h"

#include <glm/common.hpp>

namespace lagoon::optics {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kMinSunElevationDeg = 2.0;

double mean_over_grid(const Spectrum& s) {
  // (1/400)∫ over 380–780 nm, trapezoid rule on the 5 nm grid (eq. 23's normalisation).
  double sum = 0;
  for (int i = 0; i + 1 < kSamples; ++i) sum += 0.5 * (s[i] + s[i + 1]) * kLambdaStepNm;
  return sum / double(kLambdaMaxNm - kLambdaMinNm);
}

}  // namespace

SimilarScattering similarity_scaled(double scattering_per_m, double phase_x1) {
  if (phase_x1 <= kMaxModelX1) return {scattering_per_m, phase_x1};
  // Keep the transport scattering coefficient σ(1 − g) (g = X1/3), which governs the diffuse light, while
  // lowering the phase function's first moment to where the four-flow approximations stay non-negative.
  const double g = phase_x1 / 3.0, g_model = kMaxModelX1 / 3.0;
  return {scattering_per_m * (1.0 - g) / (1.0 - g_model), kMaxModelX1};
}

namespace {
constexpr double kPetzoldParticleG = 0.924;
}  // namespace

double phase_x1_at(const LutInputs& in, int i) {
  if (in.params.phase != "mixed") return in.params.phase_x1;
  const double sigma = in.water.scattering_per_m[i];
  if (sigma <= 0) return 0.0;
  const double particles = std::max(sigma - pure_seawater_scattering()[i], 0.0);
  return 3.0 * kPetzoldParticleG * particles / sigma;
}

double sun_zenith_rad(const SkyIrradiance& sky) {
  return (90.0 - std::max(sky.sun_elevation_deg, 0.0)) * kDegToRad;
}

SurfaceCoefficients lut_surface(const LutInputs& in) {
  return in.surface ? *in.surface : surface_coefficients(in.params.ior, sun_zenith_rad(in.sky));
}

Result<FourFlowSolution> solve_wavelength(const LutInputs& in, int i, double depth_m) {
  const SimilarScattering scaled = similarity_scaled(in.water.scattering_per_m[i], phase_x1_at(in, i));
  const FourFlowInput input{.absorption_per_m = in.water.absorption_per_m[i],
                            .scattering_per_m = scaled.scattering_per_m,
                            .phase_x1 = scaled.phase_x1,
                            .depth_m = depth_m,
                            .surface = lut_surface(in),
                            .bottom = lambertian_bottom(in.params.bottom_albedo),
                            .e_sun = in.sky.sun[i],
                            .e_sky = in.sky.sky[i],
                            .diffuse_path_factor = in.params.diffuse_path_factor};
  return solve_four_flow(input);
}

Spectrum downwelling_white(const SkyIrradiance& sky) {
  Spectrum w;
  for (int i = 0; i < kSamples; ++i) w[i] = sky.sun[i] + sky.sky[i];
  return w;
}

std::vector<double> lut_axis(double max_m, uint32_t n) {
  std::vector<double> axis;
  for (uint32_t i = 0; i < n; ++i) {
    const double u = double(i) / (n - 1);
    axis.push_back(max_m * u * u);  // denser near 0, where colour changes fastest
  }
  return axis;
}

Result<LutColumn> lut_column(const LutInputs& in, double depth_m) {
  LutColumn c;
  for (int i = 0; i < kSamples; ++i) {
    auto s = solve_wavelength(in, i, depth_m);
    if (!s) return s.error();
    c.at_bottom[i] = s->g_plus(s->tau0) + s->f_plus(s->tau0);
    c.upwelling[i] = s->f_minus(0.0);
    c.attenuation[i] = in.water.absorption_per_m[i] + in.water.scattering_per_m[i];
  }
  return c;
}

LutPath lut_path(const LutColumn& c, double r_m, double h_m, double gamma) {
  LutPath p;
  // At l = 0 both parts of eq. 22 are 0/0; their limits are those of a tiny path, so use one.
  const double l = std::max(std::hypot(r_m, h_m), 1e-4);
  for (int i = 0; i < kSamples; ++i) p.alpha[i] = std::exp(-c.attenuation[i] * l);
  p.mean_alpha = mean_over_grid(p.alpha);
  p.a = 1.0 - std::pow(1.0 - p.mean_alpha, gamma);
  return p;
}

namespace {

struct Entry {
  glm::dvec3 t0{0}, t1{0};
  double a = 0;
  Spectrum alpha{};
};

// One LUT entry from its column's flows: eq. 20 split as eq. 22 prescribes.
Entry entry(const LutColumn& c, const Spectrum& white, double r_m, double h_m, double gamma) {
  Entry e;
  const LutPath p = lut_path(c, r_m, h_m, gamma);
  e.alpha = p.alpha;
  e.a = p.a;
  Spectrum bottom{}, scatter{};
  for (int i = 0; i < kSamples; ++i) {
    bottom[i] = p.alpha[i] * c.at_bottom[i];
    scatter[i] = (1.0 - p.alpha[i]) * c.upwelling[i];
  }
  // T0 carries the colour of the light that reaches the eye from a white bottom, per unit of mean
  // transmission; a carries how much of it there is. T1 likewise for the scattered light.
  if (p.mean_alpha > 1e-300) e.t0 = adapted_linear_srgb(bottom, white) / p.mean_alpha;
  e.t1 = adapted_linear_srgb(scatter, white) / std::max(1.0 - p.mean_alpha, 1e-300);
  // Spectral blue-greens lie outside the sRGB gamut (a small negative red); clip to the gamut.
  e.t0 = glm::max(e.t0, glm::dvec3(0.0));
  e.t1 = glm::max(e.t1, glm::dvec3(0.0));
  return e;
}

}  // namespace

Result<LutInputs> lut_inputs(const WaterParams& params, double sun_elevation_deg, const SkyParams& sky,
                             const SlopeCovariance& slopes) {
  LutInputs in;
  in.params = params;
  auto water = params.type == "custom" ? load_water_table(params.table) : water_type(params.type);
  if (!water) return water.error();
  in.water = std::move(water).value();
  // The LUTs are ratios to the light above the water. With the sun at or below the horizon the clear-sky
  // model has no light at all, so the colours of a low (2°) sun are used; the renderer supplies darkness.
  in.sky = clear_sky(std::max(sun_elevation_deg, kMinSunElevationDeg), sky);
  if (slopes.mean_square() > 0)
    in.surface = wavy_surface_coefficients(params.ior, sun_zenith_rad(in.sky), slopes);
  return in;
}

Result<WaterLut> build_water_lut(const LutInputs& in) {
  const auto start = std::chrono::steady_clock::now();
  WaterLut lut;
  const uint32_t n = std::max(2u, in.params.lut_size);
  lut.r_count = lut.h_count = n;
  lut.r_m = lut_axis(in.params.lut_r_max_m, n);
  lut.h_m = lut_axis(in.params.lut_h_max_m, n);
  const Spectrum white = downwelling_white(in.sky);
  lut.t0.resize(size_t{n} * n * 4);
  lut.t1.resize(size_t{n} * n * 3);
  for (uint32_t j = 0; j < n; ++j) {
    auto column = lut_column(in, lut.h_m[j]);
    if (!column) return column.error();
    for (uint32_t i = 0; i < n; ++i) {
      const Entry e = entry(*column, white, lut.r_m[i], lut.h_m[j], in.params.lut_gamma);
      float* t0 = &lut.t0[(size_t{i} * n + j) * 4];
      float* t1 = &lut.t1[(size_t{i} * n + j) * 3];
      for (int c = 0; c < 3; ++c) t0[c] = float(e.t0[c]), t1[c] = float(e.t1[c]);
      t0[3] = float(e.a);
    }
  }
  auto deep = lut_column(in, 1e4);
  if (!deep) return deep.error();
  lut.deep_colour = glm::max(adapted_linear_srgb(deep->upwelling, white), glm::dvec3(0.0));
  lut.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return lut;
}

Result<LutExplain> explain_lut_point(const LutInputs& in, double r_m, double h_m) {
  if (!(r_m >= 0) || !(h_m >= 0)) return make_error("--explain R,H: r and h must be >= 0 metres");
  auto column = lut_column(in, h_m);
  if (!column) return column.error();
  LutExplain out;
  out.r_m = r_m;
  out.h_m = h_m;
  out.path_m = std::hypot(r_m, h_m);
  const Entry e = entry(*column, downwelling_white(in.sky), r_m, h_m, in.params.lut_gamma);
  out.t0 = e.t0;
  out.t1 = e.t1;
  out.a = e.a;
  for (int i = 0; i < kSamples; ++i) {
    auto s = solve_wavelength(in, i, h_m);
    if (!s) return s.error();
    LutExplain::PerWavelength w{
        .wavelength_nm = wavelength_nm(i),
        .chi = in.water.absorption_per_m[i],
        .sigma = in.water.scattering_per_m[i],
        .x1 = in.params.phase_x1,
        .k = s->k,
        .s = s->s,
        .s1 = s->s1,
        .s2 = s->s2,
        .e_sun = in.sky.sun[i],
        .e_sky = in.sky.sky[i],
        .alpha_l = e.alpha[i],
        .surface_flows = {s->g_plus(0), s->g_minus(0), s->f_plus(0), s->f_minus(0)},
        .bottom_flows = {s->g_plus(s->tau0), s->g_minus(s->tau0), s->f_plus(s->tau0), s->f_minus(s->tau0)}};
    out.spectral.push_back(w);
  }
  return out;
}

}  // namespace lagoon::optics
