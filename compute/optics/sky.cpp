#include "optics/sky.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <vector>

#include "optics/csv_table.h"

namespace lagoon::optics {
namespace {

// Bird & Riordan (1986) ozone absorption coefficient a_o, cm⁻¹ (SPCTRL2 table, after Leckner 1978), at
// their wavelengths between 370 and 780 nm (0 from 360 to 440 nm).
struct OzonePoint {
  double nm, a_o;
};
constexpr OzonePoint kOzone[] = {
    {370.0, 0.0},   {440.0, 0.0},   {450.0, 0.003}, {460.0, 0.006}, {470.0, 0.009}, {480.0, 0.014},
    {490.0, 0.021}, {500.0, 0.03},  {510.0, 0.04},  {520.0, 0.048}, {530.0, 0.063}, {540.0, 0.075},
    {550.0, 0.085}, {570.0, 0.12},  {593.0, 0.119}, {610.0, 0.12},  {630.0, 0.09},  {656.0, 0.065},
    {667.6, 0.051}, {690.0, 0.028}, {710.0, 0.018}, {718.0, 0.015}, {724.4, 0.012}, {740.0, 0.01},
    {752.5, 0.008}, {757.5, 0.007}, {762.5, 0.006}, {767.5, 0.005}, {780.0, 0.0}};

double ozone_coefficient(double nm) {
  for (std::size_t k = 1; k < std::size(kOzone); ++k) {
    if (nm <= kOzone[k].nm) {
      const double t = (nm - kOzone[k - 1].nm) / (kOzone[k].nm - kOzone[k - 1].nm);
      return kOzone[k - 1].a_o + t * (kOzone[k].a_o - kOzone[k - 1].a_o);
    }
  }
  return 0.0;
}

// ∫ of the piecewise-linear interpolant of (x, y) over [lo, hi] ⊂ [x.front(), x.back()].
double integrate_linear(const std::vector<double>& x, const std::vector<double>& y, double lo, double hi) {
  auto value = [&](std::size_t j, double at) {  // on segment [x[j], x[j+1]]
    return y[j] + (at - x[j]) / (x[j + 1] - x[j]) * (y[j + 1] - y[j]);
  };
  double sum = 0.0;
  for (std::size_t j = 0; j + 1 < x.size(); ++j) {
    const double a = std::max(lo, x[j]), b = std::min(hi, x[j + 1]);
    if (b > a) sum += 0.5 * (value(j, a) + value(j, b)) * (b - a);
  }
  return sum;
}

}  // namespace

const Spectrum& extraterrestrial_irradiance() {
  static const Spectrum h0 = [] {
    const CsvTable t = embedded_table_or_abort("astm_g173_380_780.csv");
    const std::vector<double> nm = numbers_or_abort(t, "wavelength_nm");
    const std::vector<double> e = numbers_or_abort(t, "extraterrestrial_W_m2_nm");
    for (std::size_t r = 1; r < nm.size(); ++r)
      if (!(nm[r] > nm[r - 1])) abort_table_defect(t.where(r, "wavelength_nm") + ": not increasing");
    if (nm.front() > kLambdaMinNm || nm.back() < kLambdaMaxNm)
      abort_table_defect(t.source() + ": does not cover 380-780 nm");
    Spectrum out{};
    for (int i = 0; i < kSamples; ++i) {
      const double lo = std::max(wavelength_nm(i) - 0.5 * kLambdaStepNm, double{kLambdaMinNm});
      const double hi = std::min(wavelength_nm(i) + 0.5 * kLambdaStepNm, double{kLambdaMaxNm});
      out[i] = integrate_linear(nm, e, lo, hi) / (hi - lo);
    }
    return out;
  }();
  return h0;
}

SkyIrradiance clear_sky(double sun_elevation_deg, const SkyParams& p) {
  SkyIrradiance out{{}, {}, sun_elevation_deg};
  const double elevation = std::clamp(sun_elevation_deg, 0.0, 90.0);
  const double zenith_deg = 90.0 - elevation;
  const double cos_z = std::sin(elevation * std::numbers::pi / 180.0);
  if (!(cos_z > 0.0)) return out;  // at or below the horizon (or NaN): no sun, no sky
  const double air_mass = 1.0 / (cos_z + 0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
  const double pressure_air_mass = air_mass * p.surface_pressure_hpa / 1013.25;
  const double h_o = 22.0 / 6370.0;  // ozone layer height / Earth radius
  const double ozone_air_mass = (1.0 + h_o) / std::sqrt(cos_z * cos_z + 2.0 * h_o);
  const double alg = std::log(1.0 - 0.65);
  const double afs = alg * (1.459 + alg * (0.1595 + alg * 0.4129));
  const double bfs = alg * (0.0783 + alg * (-0.3824 - alg * 0.5874));
  const double forward = 1.0 - 0.5 * std::exp((afs + bfs * cos_z) * cos_z);  // F_s
  const Spectrum& h0 = extraterrestrial_irradiance();
  for (int i = 0; i < kSamples; ++i) {
    const double um = wavelength_nm(i) / 1000.0;
    const double t_r = std::exp(-pressure_air_mass / (std::pow(um, 4) * (115.6406 - 1.335 / (um * um))));
    const double tau_a = p.aerosol_optical_depth_500nm * std::pow(um / 0.5, -p.angstrom_alpha);
    const double albedo = 0.945 * std::exp(-0.095 * std::pow(std::log(um / 0.4), 2));
    const double t_a = std::exp(-tau_a * air_mass);
    const double t_aa = std::exp(-(1.0 - albedo) * tau_a * air_mass);
    const double t_as = std::exp(-albedo * tau_a * air_mass);
    const double t_o = std::exp(-ozone_coefficient(wavelength_nm(i)) * p.ozone_cm * ozone_air_mass);
    const double c_s = um <= 0.45 ? std::pow(um + 0.55, 1.8) : 1.0;
    const double top = h0[i] * cos_z;  // extraterrestrial irradiance on a horizontal plane
    out.sun[i] = top * t_r * t_a * t_o;
    const double rayleigh = 0.5 * (1.0 - std::pow(t_r, 0.95));
    const double aerosol = std::pow(t_r, 1.5) * (1.0 - t_as) * forward;
    out.sky[i] = c_s * top * t_o * t_aa * (rayleigh + aerosol);
  }
  return out;
}

}  // namespace lagoon::optics
