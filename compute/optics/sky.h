// A clear-sky spectral irradiance model on the optics grid (spectrum.h): E_sun and E_sky of Belyaev's
// eq. 7, for the water-colour LUTs. The renderer's sky has to agree with it, so the formulas are kept short
// and all listed here. It is Bird & Riordan (1986), "Simple solar spectral model for direct and diffuse
// irradiance on horizontal and tilted planes at the earth's surface for cloudless atmospheres" (J. Clim.
// Appl. Meteorol. 25, 87-97; NREL SPCTRL2), restricted to 380-780 nm. λ in µm below; Z = 90° − elevation.
//
//   H0(λ)   ASTM G173-03 extraterrestrial spectrum (W m⁻² nm⁻¹) at the mean Earth–Sun distance; each 5 nm
//           sample is the mean of the table over [λ − 2.5, λ + 2.5] nm (cut to 380-780 at the two ends):
//           the integral of the piecewise-linear interpolant of the 0.5/1 nm data divided by the bin width.
//   M       Kasten & Young (1989) relative air mass 1 / (cos Z + 0.50572·(96.07995° − Z)^−1.6364), Z ≤ 90°
//           (M ≤ 37.9 at the horizon); M' = M·p/1013.25 hPa.
//   T_R     Rayleigh: exp(−M' / (λ⁴·(115.6406 − 1.335/λ²))).
//   τ_a     Ångström aerosol optical depth τ500·(λ/0.5)^−α; T_a = exp(−τ_a·M).
//   ω       aerosol single-scattering albedo 0.945·exp(−0.095·ln²(λ/0.4)) (Bird's rural aerosol);
//           T_aa = exp(−(1 − ω)·τ_a·M) (aerosol absorption), T_as = exp(−ω·τ_a·M) (aerosol scattering).
//   T_o     ozone: exp(−a_o(λ)·ozone_cm·M_o), M_o = (1 + 22/6370) / sqrt(cos²Z + 2·22/6370); a_o (cm⁻¹) is
//           Bird & Riordan's Chappuis-band table (from Leckner 1978), interpolated linearly; peak 0.12 near
//           600 nm, 0 below 440 nm.
//   sun  = H0·cos Z·T_R·T_a·T_o                                   (direct beam on a horizontal surface)
//   sky  = C_s·H0·cos Z·T_o·T_aa·[0.5·(1 − T_R^0.95) + T_R^1.5·(1 − T_as)·F_s]   (diffuse, horizontal)
//          F_s = 1 − 0.5·exp((AFS + BFS·cos Z)·cos Z): the aerosol forward-scattered fraction for
//          asymmetry <cos θ> = 0.65 (AFS, BFS: Bird & Riordan eqs. 3-12..3-14, ALG = ln(1 − 0.65));
//          C_s = (λ + 0.55)^1.8 for λ ≤ 0.45 µm, else 1 (their empirical blue correction).
// Left out (state this when comparing): water vapour (720 nm band) and O2 (760 nm A band) absorption,
// where the CIE ȳ is below 0.001, the Earth–Sun distance correction (±3.4 % over the year), and the
// ground–sky multiple reflection term (over an ocean of albedo ~0.06 it adds ~1 %).
// At 60° elevation with the defaults, ∫380-780 nm (5 nm rectangle sum): sun 444 W m⁻², sky 69 W m⁻²,
// global 513 W m⁻², chromaticity (0.3286, 0.3387) (D65: 0.3127, 0.3290); ET H0 over the band: 662 W m⁻².
// For elevation ≤ 0 both terms are 0 (cos Z is clamped at 0, continuous at the horizon): no twilight.
#pragma once
#include "optics/spectrum.h"

namespace lagoon::optics {

struct SkyParams {
  double aerosol_optical_depth_500nm = 0.1;  // τ500: 0.05 very clean maritime .. 0.5 hazy
  double angstrom_alpha = 1.3;               // Ångström exponent (Bird's rural aerosol uses 1.14)
  double ozone_cm = 0.3;                     // total ozone column, atm-cm (300 Dobson units)
  double surface_pressure_hpa = 1013.25;
};

struct SkyIrradiance {
  Spectrum sun;  // direct beam on a HORIZONTAL surface, W m⁻² nm⁻¹ (zero when the sun is below the horizon)
  Spectrum sky;  // diffuse sky on a horizontal surface, W m⁻² nm⁻¹
  double sun_elevation_deg = 0.0;
};

SkyIrradiance clear_sky(double sun_elevation_deg, const SkyParams& params = {});

// H0(λ): the ASTM G173-03 extraterrestrial spectrum averaged over each 5 nm bin, W m⁻² nm⁻¹.
const Spectrum& extraterrestrial_irradiance();

}  // namespace lagoon::optics
