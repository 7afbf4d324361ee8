// Wave spectra. Frequency spectra S(ω) [m²·s] (variance of the surface height per rad/s, ∫S dω = Var η) and
// the directional wavenumber spectrum Ψ(kx, kz) [m⁴] (∫∫Ψ dkx dkz = Var η) that the FFT ocean samples.
// Formulas: seed text 14-15, Horvath 2015 "Empirical directional wave spectra for computer graphics" §5.
#pragma once
#include "ocean/dispersion.h"
#include "ocean/ocean_params.h"
#include "ocean/spreading.h"

namespace lagoon::ocean {

inline constexpr double kPiersonMoskowitzAlpha = 0.0081;  // Phillips' constant (seed formula 14)
inline constexpr double kPhillipsAlpha = 0.0081;          // same saturation range for the Phillips spectrum

// α g² ω⁻⁵ exp(-5/4 (ω_p/ω)⁴): the Pierson-Moskowitz shape; 0 at ω <= 0.
double pierson_moskowitz(double omega, double alpha, double peak_omega);
// PM shape × γ^r, r = exp(-(ω-ω_p)²/(2σ²ω_p²)), σ = 0.07 for ω <= ω_p, 0.09 above.
double jonswap(double omega, double alpha, double peak_omega, double gamma);
// Kitaigorodskii depth attenuation Φ(ω_h), ω_h = ω sqrt(h/g): ω_h²/2 up to 1, 1 - (2-ω_h)²/2 up to 2, then 1.
double kitaigorodskii(double omega_h);

// PM peak (seed 14): ω_p = 2π · 0.13 g/U, rad/s.
double pierson_moskowitz_peak_omega(double wind_speed_mps);
// Fetch-limited JONSWAP (Horvath eq. 28-29): α = 0.076 (U²/(F g))^0.22, ω_p = 22 (g²/(U F))^(1/3).
// The raw laws, valid below full development only: sea_development() is what the spectra use.
double jonswap_alpha(double wind_speed_mps, double fetch_m);
double jonswap_peak_omega(double wind_speed_mps, double fetch_m);

// The dimensionless fetch gF/U² at which JONSWAP's peak reaches Pierson–Moskowitz's, 22 χ^(-1/3) =
// 2π·0.13: χ = (22 / (2π·0.13))³ ≈ 1.95e4. A sea this developed no longer grows with fetch.
double fully_developed_fetch();

// JONSWAP's α, ω_p and γ at a fetch, growing into Pierson–Moskowitz's sea at full development (issue 33):
// below a tenth of the fully developed fetch the fetch laws above with the given γ; from there to full
// development γ falls to 1 and α to PM's 0.0081, both log-linearly in χ, while ω_p follows its fetch law
// to PM's peak; beyond it the PM sea. Continuous, and the height never falls as the fetch grows (the
// α ω_p⁻⁴ growth, χ^1.11, outpaces the loss of the peak enhancement, at most 1.63x for γ = 3.3, over the
// decade). `cap` false: the raw fetch laws at any fetch.
struct SeaDevelopment {
  double alpha = 0, peak_omega = 0, gamma = 1;
};
SeaDevelopment sea_development(double wind_speed_mps, double fetch_m, double gamma, bool cap = true);

// Phillips as a frequency spectrum with PM's saturation range (our choice, so all four spectra share the
// ω⁻⁵ tail and α): S(ω) = α g² ω⁻⁵ exp(-1/(kL)²) exp(-k²l²), k = ω²/g (deep water), L = U²/g,
// l = small_wave_cutoff_m. In wavenumbers this is Tessendorf's α/(2k⁴) · exp(-1/(kL)²) per unit D(θ).
double phillips(double omega, double wind_speed_mps, double small_wave_cutoff_m);

// Seed 001 eq. 18 (Tessendorf's Phillips spectrum) as a density in wavenumber: A exp(-1/(kL)²) / k⁴ ·
// |cos φ|^p, L = U²/g, φ the angle from the wind; and its integral over direction, ∫|cos φ|^p dφ =
// 2√π Γ((p+1)/2) / Γ(p/2+1) (π at p = 2).
double phillips_eq18(double k, double cos_phi, const SpectrumParams& spectrum);
double cos_power_integral(double p);

// The spectral peak ω_p (rad/s) that also scales the spreading: PM and JONSWAP/TMA as above, Phillips'
// undamped maximum (4/5)^(1/4) g/U.
double peak_omega(const SpectrumParams& spectrum);
// S(ω) [m²·s] of spectrum.type; depth_m only matters for TMA (JONSWAP × Φ(ω sqrt(h/g))). 0 at ω <= 0.
double frequency_spectrum(const SpectrumParams& spectrum, double depth_m, double omega);

// Ψ(k) = S(ω(k)) D(ω, θ) (dω/dk) / k with the unquantised finite-depth, capillary ω(k); θ is the angle of k
// from the wind vector compass::toward(φ) in (x, z), φ = wind_direction_deg. Everything that does not depend
// on k is computed once in the constructor, so sampling a grid costs one dispersion, one S and one D per
// mode.
class DirectionalSpectrum {
 public:
  explicit DirectionalSpectrum(const OceanParams& params);
  double operator()(double kx, double kz) const;  // Ψ, m⁴; 0 at k = 0
  double omnidirectional(double k) const;         // S(ω(k)) dω/dk, m³ (∫ over k >= 0 gives Var η)
  double frequency(double omega) const;           // S(ω), m²·s
  const DispersionModel& dispersion() const { return dispersion_; }
  const SpreadingModel& spreading_model() const { return spreading_; }

 private:
  SpectrumParams spectrum_;
  double depth_m_;
  DispersionModel dispersion_;  // loop period 0: the spectrum uses the physical ω
  SpreadingModel spreading_;
  SeaDevelopment shape_;  // α, ω_p and γ
  double wind_x_ = 0, wind_z_ = 1;
};

double directional_spectrum(const OceanParams& params, double kx, double kz);
double omnidirectional_wavenumber_spectrum(const OceanParams& params, double k);

}  // namespace lagoon::ocean
