// The capillary-gravity waves shorter than the last cascade, as Elfouhaily, Chapron, Katsaros & Vandemark
// (1997, "A unified directional spectrum for long and short wind-driven waves", JGR 102(C7), eqs. 40-44,
// 49-57) give them: the short-wave curvature spectrum B_h(k) = ½ α_m (c_m/c) F_m(k), peaked at the
// capillary-gravity wavenumber k_m = 370 rad/m, with an amplitude α_m that grows with the friction velocity
// u*, and its spreading 1 + Δ(k) cos 2φ. These are the slopes that widen the sun's glint and roughen the
// water colour: the model was built to reproduce Cox & Munk's (1954) slope statistics, which the JONSWAP
// saturation tail (a wind-independent α/2 to 1 cm) cannot (its slopes grow only as ln U).
#pragma once
#include "ocean/ocean_params.h"
#include "ocean/slope_statistics.h"

namespace lagoon::ocean {

// Friction velocity u* = sqrt(C_d) U10 with Wu's (1982) drag C_d = (0.8 + 0.065 U10) 1e-3, m/s.
double friction_velocity(double wind_speed_mps);

// B_h(k) (dimensionless curvature, k³ × the omnidirectional wavenumber spectrum) for the scene's wind and
// peak; 0 where α_m <= 0 (u* below c_m/e: no capillaries on a glassy sea).
double short_wave_curvature(const OceanParams& params, double k);

// Elfouhaily's spreading Δ(k) in [0, 1): the directional spectrum is B/(2π k⁴) (1 + Δ cos 2φ).
double short_wave_spreading(const OceanParams& params, double k);

// The slope moments of B_h from k_from up to where it vanishes (10 k_m), along the scene's wind: what the
// cascades leave out.
SlopeMoments short_wave_slope_moments(const OceanParams& params, double k_from);

}  // namespace lagoon::ocean
