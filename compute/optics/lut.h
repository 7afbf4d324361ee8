// The colour look-up tables of eq. 22: the refracted colour T_refr = a·T0·T_bottom + (1 − a)·T1 as a function
// of r, the horizontal distance the refracted view ray travels under water, and h, the depth of the bottom
// where it ends (docs/optics.md derives both and the path length l(r, h) = sqrt(r² + h²)).
//
// Units (scene-referred): linear sRGB relative to the downwelling light above the water: under the sun and
// sky of the LUT, a white Lambertian surface above the water has RGB (1, 1, 1). The renderer multiplies by
// the radiance it gives such a surface, and tone-maps the whole frame once.
#pragma once
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "optics/four_flow.h"
#include "optics/rough_surface.h"
#include "optics/sky.h"
#include "optics/spectrum.h"
#include "optics/water_params.h"
#include "optics/water_types.h"

namespace lagoon::optics {

struct WaterLut {
  uint32_t r_count = 0, h_count = 0;
  std::vector<double> r_m, h_m;  // axis values: r_m[i] = r_max (i/(R−1))², h_m[j] = h_max (j/(H−1))²
  std::vector<float> t0;         // [r][h][4]: RGB of T0, alpha = a(r, h)
  std::vector<float> t1;         // [r][h][3]: RGB of T1
  glm::dvec3 deep_colour{0};     // T1 of bottomless water (h -> ∞, r = 0): the colour beyond the LUT
  double build_ms = 0;
};

struct LutInputs {
  WaterIops water;
  WaterParams params;
  SkyIrradiance sky;
  // The surface's coefficients when it is wavy (eq. 10, rough_surface.h); empty = the flat surface's at the
  // sky's sun.
  std::optional<SurfaceCoefficients> surface;
};

// The seed's four-flow coefficients (S = σ(1 − X1/2)/ε, S2 = σ(1 − X1)/(2ε)) turn negative for strongly
// forward scattering (ocean particles: X1 ≈ 2.75), giving negative light. Above X1 = 1 the scattering is
// replaced by a similar one (same σ(1 − g), g = X1/3) with X1 = 1. Bouguer's α_l keeps the true σ.
inline constexpr double kMaxModelX1 = 1.0;
struct SimilarScattering {
  double scattering_per_m, phase_x1;
};
SimilarScattering similarity_scaled(double scattering_per_m, double phase_x1);

// The pieces every table built from the four-flow model shares (this file's LUTs, underwater.h):
// X1 at grid wavelength i under params.phase; the flows of one wavelength for a bottom at depth_m, with the
// scattering similarity-scaled as above; and the white Φ adapts to, E_sun + E_sky above the water.
double phase_x1_at(const LutInputs& inputs, int i);
// The sun's zenith angle the tables are built for (the sky's sun, clamped to the horizon), radians; and the
// surface coefficients they use: the wavy sea's when the inputs have them, else the flat surface's there.
double sun_zenith_rad(const SkyIrradiance& sky);
SurfaceCoefficients lut_surface(const LutInputs& inputs);
Result<FourFlowSolution> solve_wavelength(const LutInputs& inputs, int i, double depth_m);
Spectrum downwelling_white(const SkyIrradiance& sky);

// The LUT axes: value i of n is max (i/(n−1))², denser near 0 where the colour changes fastest.
std::vector<double> lut_axis(double max_m, uint32_t n);
// The flows one LUT column (a bottom at depth_m) needs, per wavelength.
struct LutColumn {
  Spectrum at_bottom;    // G+(τ0) + F+(τ0): light arriving at the bottom
  Spectrum upwelling;    // F−(0): diffuse light leaving the water column upwards, average bottom
  Spectrum attenuation;  // ε = χ + σ
};
Result<LutColumn> lut_column(const LutInputs& inputs, double depth_m);
// Bouguer's α_l(λ) along the path l = sqrt(r² + h²) (a 0.1 mm path at l = 0, the limit eq. 22's parts
// take), its mean ᾱ over 380–780 nm and eq. 23's a = 1 − (1 − ᾱ)^γ.
struct LutPath {
  Spectrum alpha{};
  double mean_alpha = 0, a = 0;
};
LutPath lut_path(const LutColumn& column, double r_m, double h_m, double gamma);

// `slopes`: the sea's slope covariance, for eq. 10's wavy surface (zero: the flat surface).
Result<LutInputs> lut_inputs(const WaterParams& params, double sun_elevation_deg, const SkyParams& sky = {},
                             const SlopeCovariance& slopes = {});

Result<WaterLut> build_water_lut(const LutInputs& inputs);

// Everything behind one LUT entry, per wavelength (lagoon lut --explain).
struct LutExplain {
  double r_m = 0, h_m = 0, path_m = 0;
  struct PerWavelength {
    double wavelength_nm, chi, sigma, x1, k, s, s1, s2, e_sun, e_sky, alpha_l;
    double surface_flows[4];  // G+, G−, F+, F− at τ = 0
    double bottom_flows[4];   // at τ0
  };
  std::vector<PerWavelength> spectral;
  glm::dvec3 t0{0}, t1{0};
  double a = 0;
};
Result<LutExplain> explain_lut_point(const LutInputs& inputs, double r_m, double h_m);

}  // namespace lagoon::optics
