#include "ocean/spectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/compass.h"

namespace lagoon::ocean {
namespace {

constexpr double kG = kGravity;

double fetch_m(const SpectrumParams& s) {
  return s.fetch_km * 1000.0;
}

SeaDevelopment development(const SpectrumParams& s) {
  return sea_development(s.wind_speed_mps, fetch_m(s), s.gamma, s.cap_at_full_development);
}

// γ as the sea has developed: the scene's below a tenth of full development, 1 at it.
double peak_enhancement(const SpectrumParams& s) {
  return s.type == SpectrumType::Jonswap || s.type == SpectrumType::Tma ? development(s).gamma : s.gamma;
}

// α of the ω⁻⁵ range for each type.
double spectrum_alpha(const SpectrumParams& s) {
  switch (s.type) {
    case SpectrumType::Phillips:
      return kPhillipsAlpha;
    case SpectrumType::PiersonMoskowitz:
      return kPiersonMoskowitzAlpha;
    case SpectrumType::Jonswap:
    case SpectrumType::Tma:
      return development(s).alpha;
    case SpectrumType::JonswapEq15:
      return kPiersonMoskowitzAlpha;  // eq. 14's 0.0081
    case SpectrumType::PhillipsEq18:
      return 0.0;  // its own amplitude
  }
  return 0.0;
}

// Everything of S(ω) that does not depend on ω, once.
SeaDevelopment shape_of(const SpectrumParams& s) {
  return {spectrum_alpha(s), peak_omega(s), peak_enhancement(s)};
}

// Eq. 18's omnidirectional density in k, ∫ P dφ · k (m³).
double phillips_eq18_omnidirectional(double k, const SpectrumParams& s) {
  return phillips_eq18(k, 1.0, s) * cos_power_integral(s.directional_exponent) * k;
}

// S(ω) with α, ω_p and γ already known.
double evaluate(const SpectrumParams& s, const SeaDevelopment& shape, double depth_m, double omega) {
  if (!(omega > 0.0)) return 0.0;
  const double alpha = shape.alpha, peak = shape.peak_omega;
  switch (s.type) {
    case SpectrumType::Phillips:
      return phillips(omega, s.wind_speed_mps, s.small_wave_cutoff_m);
    case SpectrumType::PiersonMoskowitz:
      return pierson_moskowitz(omega, alpha, peak);
    case SpectrumType::Jonswap:
      return jonswap(omega, alpha, peak, shape.gamma);
    case SpectrumType::Tma:
      return jonswap(omega, alpha, peak, shape.gamma) * kitaigorodskii(omega * std::sqrt(depth_m / kG));
    case SpectrumType::JonswapEq15:
      return jonswap(omega, alpha, peak, 3.3);  // eq. 15's ln(3.3): γ fixed at 3.3
    case SpectrumType::PhillipsEq18: {
      const double k = omega * omega / kG;  // deep water: the form is given in k, S(ω) only for plots
      return phillips_eq18_omnidirectional(k, s) * 2.0 * omega / kG;
    }
  }
  return 0.0;
}

}  // namespace

double pierson_moskowitz(double omega, double alpha, double peak_omega) {
  if (!(omega > 0.0)) return 0.0;
  const double r4 = std::pow(peak_omega / omega, 4.0);
  return alpha * kG * kG * std::pow(omega, -5.0) * std::exp(-1.25 * r4);
}

double jonswap(double omega, double alpha, double peak_omega, double gamma) {
  if (!(omega > 0.0)) return 0.0;
  const double sigma = omega <= peak_omega ? 0.07 : 0.09;
  const double d = (omega - peak_omega) / (sigma * peak_omega);
  const double r = std::exp(-0.5 * d * d);
  return pierson_moskowitz(omega, alpha, peak_omega) * std::pow(gamma, r);
}

double kitaigorodskii(double omega_h) {
  if (omega_h <= 1.0) return 0.5 * omega_h * omega_h;
  if (omega_h < 2.0) return 1.0 - 0.5 * (2.0 - omega_h) * (2.0 - omega_h);
  return 1.0;
}

double pierson_moskowitz_peak_omega(double wind_speed_mps) {
  return 2.0 * std::numbers::pi * 0.13 * kG / wind_speed_mps;
}

double jonswap_alpha(double wind_speed_mps, double fetch_m) {
  return 0.076 * std::pow(wind_speed_mps * wind_speed_mps / (fetch_m * kG), 0.22);
}

double jonswap_peak_omega(double wind_speed_mps, double fetch_m) {
  return 22.0 * std::cbrt(kG * kG / (wind_speed_mps * fetch_m));
}

double fully_developed_fetch() {
  const double r = 22.0 / (2.0 * std::numbers::pi * 0.13);
  return r * r * r;
}

SeaDevelopment sea_development(double wind_speed_mps, double fetch_m, double gamma, bool cap) {
  const double u2_g = wind_speed_mps * wind_speed_mps / kG;
  const double chi = fetch_m / u2_g, chi_full = fully_developed_fetch();
  if (!cap || chi <= 0.1 * chi_full)
    return {jonswap_alpha(wind_speed_mps, fetch_m), jonswap_peak_omega(wind_speed_mps, fetch_m), gamma};
  const double grown = std::min(std::log10(chi / chi_full) + 1.0, 1.0);  // 0 at χ_full/10, 1 at χ_full
  const double fetch = std::min(chi, chi_full) * u2_g;
  const double alpha_full = jonswap_alpha(wind_speed_mps, chi_full * u2_g);
  return {jonswap_alpha(wind_speed_mps, fetch) * std::pow(kPiersonMoskowitzAlpha / alpha_full, grown),
          jonswap_peak_omega(wind_speed_mps, fetch), std::pow(gamma, 1.0 - grown)};
}

double phillips(double omega, double wind_speed_mps, double small_wave_cutoff_m) {
  if (!(omega > 0.0)) return 0.0;
  const double k = omega * omega / kG;
  const double kl_big = k * wind_speed_mps * wind_speed_mps / kG;  // kL, L = U²/g
  const double kl_small = k * small_wave_cutoff_m;
  return kPhillipsAlpha * kG * kG * std::pow(omega, -5.0) * std::exp(-1.0 / (kl_big * kl_big)) *
         std::exp(-kl_small * kl_small);
}

double phillips_eq18(double k, double cos_phi, const SpectrumParams& s) {
  if (!(k > 0.0)) return 0.0;
  const double big_l = s.wind_speed_mps * s.wind_speed_mps / kG;
  const double kl = k * big_l;
  return s.amplitude * std::exp(-1.0 / (kl * kl)) / (k * k * k * k) *
         std::pow(std::abs(cos_phi), s.directional_exponent);
}

double cos_power_integral(double p) {
  return 2.0 * std::sqrt(std::numbers::pi) * std::tgamma(0.5 * (p + 1.0)) / std::tgamma(0.5 * p + 1.0);
}

double peak_omega(const SpectrumParams& s) {
  switch (s.type) {
    case SpectrumType::Phillips:
      return std::pow(0.8, 0.25) * kG / s.wind_speed_mps;
    case SpectrumType::PiersonMoskowitz:
      return pierson_moskowitz_peak_omega(s.wind_speed_mps);
    case SpectrumType::Jonswap:
    case SpectrumType::Tma:
      return development(s).peak_omega;
    case SpectrumType::JonswapEq15:
      return pierson_moskowitz_peak_omega(s.wind_speed_mps);  // eq. 14's f_m = 0.13 g / U10
    case SpectrumType::PhillipsEq18:  // the maximum of k⁻³ exp(-1/(kL)²): k = sqrt(2/3) / L
      return std::sqrt(kG * std::sqrt(2.0 / 3.0) * kG / (s.wind_speed_mps * s.wind_speed_mps));
  }
  return 1.0;
}

double frequency_spectrum(const SpectrumParams& s, double depth_m, double omega) {
  return evaluate(s, shape_of(s), depth_m, omega);
}

DirectionalSpectrum::DirectionalSpectrum(const OceanParams& params)
    : spectrum_(params.spectrum),
      depth_m_(params.depth_m),
      dispersion_{params.depth_m, true, 0.0},
      spreading_(spreading_for(params.spectrum)),
      shape_(shape_of(params.spectrum)) {
  const glm::dvec2 wind = compass::toward_deg(params.spectrum.wind_direction_deg);
  wind_x_ = wind.x;
  wind_z_ = wind.y;
}

double DirectionalSpectrum::frequency(double omega) const {
  return evaluate(spectrum_, shape_, depth_m_, omega);
}

double DirectionalSpectrum::omnidirectional(double k) const {
  if (!(k > 0.0)) return 0.0;
  if (spectrum_.type == SpectrumType::PhillipsEq18) return phillips_eq18_omnidirectional(k, spectrum_);
  return frequency(omega(dispersion_, k)) * domega_dk(dispersion_, k);
}

double DirectionalSpectrum::operator()(double kx, double kz) const {
  const double k = std::hypot(kx, kz);
  if (!(k > 0.0)) return 0.0;
  if (spectrum_.type == SpectrumType::PhillipsEq18)  // given in k with its own directional factor
    return phillips_eq18(k, (kx * wind_x_ + kz * wind_z_) / k, spectrum_);
  const double w = omega(dispersion_, k);
  const double s = frequency(w);
  if (s == 0.0) return 0.0;
  const double theta = std::atan2(kx * wind_z_ - kz * wind_x_, kx * wind_x_ + kz * wind_z_);
  return s * spreading(spreading_, w, theta) * domega_dk(dispersion_, k) / k;
}

double directional_spectrum(const OceanParams& params, double kx, double kz) {
  return DirectionalSpectrum(params)(kx, kz);
}

double omnidirectional_wavenumber_spectrum(const OceanParams& params, double k) {
  return DirectionalSpectrum(params).omnidirectional(k);
}

}  // namespace lagoon::ocean
