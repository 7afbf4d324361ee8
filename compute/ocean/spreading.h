// Directional spreading D(ω, θ) [1/rad]: how a frequency's energy is shared between directions θ, measured
// from the wind direction in radians. Every model integrates to 1 over θ in (-π, π] (Horvath 2015, §5.2).
#pragma once
#include "ocean/ocean_params.h"

namespace lagoon::ocean {

// What D needs from the spectrum, computed once (see spreading_for).
struct SpreadingModel {
  Spreading type = Spreading::Cos2s;
  double peak_omega = 1.0;  // ω_p of the frequency spectrum, rad/s (> 0)
  double s_peak = 1.0;      // Mitsuyasu's s_p = 11.5 (U/c_p)^-2.5, c_p = g/ω_p: cos-2s exponent at the peak
  double swell = 0.0;       // Horvath's ξ in [0, 1]
};

SpreadingModel spreading_for(const SpectrumParams& spectrum);

// D(ω, θ) for ω > 0 (rad/s) and any θ (wrapped into (-π, π]); 1/(2π) (isotropic) at ω <= 0.
//  Cos2:          (2/π) cos²θ for |θ| < π/2, 0 behind the wind.
//  Cos2s:         Q(s) |cos(θ/2)|^(2s), s = Mitsuyasu s(ω) + swell s_ξ(ω).
//  DonelanBanner: β/(2 tanh(βπ)) sech²(βθ), β = donelan_banner_beta(ω/ω_p).
// Swell for Cos2 and DonelanBanner multiplies by |cos(θ/2)|^(2 s_ξ) and divides by the integral of the
// product, read from a table built once per process (bicubic, relative error < 1e-4).
double spreading(const SpreadingModel& model, double omega, double theta);
double spreading(const SpectrumParams& spectrum, double omega, double theta);

// Mitsuyasu/Hasselmann s(ω): s_p (ω/ω_p)^5 below the peak, s_p (ω/ω_p)^-2.5 above; no swell.
double cos2s_exponent(const SpreadingModel& model, double omega);
// Horvath's swell exponent s_ξ = 16 tanh(ω_p/ω) ξ², in [0, 16]; 0 when ω <= 0 or ξ = 0.
double swell_exponent(double omega, double peak_omega, double swell);
// Q(s) = 2^(2s-1)/π Γ(s+1)²/Γ(2s+1) so that ∫ Q |cos(θ/2)|^(2s) dθ = 1 over (-π, π]; s >= 0, via lgamma.
double cos2s_normalisation(double s);
// Donelan-Banner β_s (dimensionless) for r = ω/ω_p > 0: 2.61 r^1.3 for 0.56 < r < 0.95, 2.28 r^-1.3 for
// 0.95 <= r < 1.6, else 10^ε with ε = -0.4 + 0.8393 exp(-0.567 ln r²) (Banner 1990, as in Horvath 2015).
// Clamped to 1e4 (a lobe 1e-4 rad wide) so far below the peak, where the spectrum is 0, it stays finite.
double donelan_banner_beta(double omega_over_peak);

}  // namespace lagoon::ocean
