// Dispersion relation ω(k) of surface gravity-capillary waves: how fast (rad/s) a wave of wavenumber k
// (rad/m) oscillates. Seed formulas 7-9 combined into one expression, plus the loop quantisation of
// formula 10.
#pragma once
#include "ocean/ocean_params.h"

namespace lagoon::ocean {

inline constexpr double kWaterDensity = 1000.0;   // ρ, kg/m³
inline constexpr double kSurfaceTension = 0.074;  // σ, N/m (clean water at ~20 °C)
// k_m² = ρg/σ: the wavenumber (≈ 364 rad/m, λ ≈ 1.7 cm) where gravity and surface tension restore equally.
inline constexpr double kCapillaryK2 = kWaterDensity * kGravity / kSurfaceTension;

struct DispersionModel {
  double depth_m = 1000.0;     // D > 0; tanh(kD) -> 1 once kD > ~10 (deep water)
  bool capillary = true;       // include surface tension: the (1 + k²/k_m²) factor
  double loop_period_s = 0.0;  // T > 0 quantises ω to multiples of 2π/T (seed formula 10); 0 = off
};

// The model the ocean uses: finite depth, capillary term on, the scene's loop period.
DispersionModel dispersion_for(const OceanParams& params);

// ω(k) = sqrt(g k tanh(kD) (1 + k²/k_m²)), rad/s, for k >= 0 (0 at k <= 0); quantised to
// floor(ω T/2π)·2π/T when model.loop_period_s > 0, so it never exceeds the unquantised value.
double omega(const DispersionModel& model, double k);
// dω/dk (m/s, the group velocity) of the unquantised ω; at k = 0 the shallow-water limit sqrt(gD).
double domega_dk(const DispersionModel& model, double k);

double omega_deep(double k);                          // sqrt(g k): seed formula 7
double omega_finite_depth(double k, double depth_m);  // sqrt(g k tanh(kD)): seed formula 8
double omega_capillary(double k);                     // sqrt(g k (1 + k²/k_m²)): seed formula 9, deep water
// floor(ω T/2π)·2π/T; ω unchanged when period_s <= 0.
double quantise_omega(double omega, double period_s);

}  // namespace lagoon::ocean
