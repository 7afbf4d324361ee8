// Heave added mass and radiation damping (issue 33, opt-in): the water a heaving body pushes aside moves
// with it (added mass a) and radiates waves that carry energy away (damping b), which the hydrostatic
// pressure (physics/hydrostatics.h) leaves out. Without them a half-submerged sphere heaves with the period
// 2π·sqrt(m/K) of its mass on the waterplane's stiffness K = ρgA_wp, 17 % short of its true one.
// The model: the floating hemisphere of the same displaced volume V (radius r = (3V/2π)^⅓), with Hulme's
// (1982, J. Fluid Mech. 121) coefficients a = μ·ρV and b = ν·ρV·ω taken at the heave resonance
// ω_n² = 3g/(2r(1 + μ)), where kr = 1.055 in deep water: μ = 0.422, ν = 0.238 (Hulme's table, as
// transcribed in LHEEA/Hulme_Heaving_Sphere, interpolated there; `lagoon validate`'s bodies.sphere-* laws
// use the whole table). One frequency only (no memory kernel): right for free decay (the Task 10 sphere's
// period within 2 %). In waves they act on the heave relative to the water's motion at the hemisphere's
// centre of buoyancy (physics/floating_body.cpp), the long-wave approximation of the diffraction force:
// the Task 10 RAO within 14 % of linear theory from 4.4 to 11 s, not below 4 s (docs/validation.md).
// V is the volume under the water now, so a body in the air gets neither.
#pragma once

namespace lagoon::physics {

struct HeaveRadiation {
  bool enabled = false;
  double added_mass = 0.422;  // μ = a / (ρV)
  double damping = 0.238;     // ν = b / (ρVω)
};

struct HeaveTerms {
  double added_mass_kg = 0;
  double damping_n_s_per_m = 0;  // against the body's vertical velocity relative to the water's
  double buoyancy_depth_m = 0;   // of the hemisphere's centre of buoyancy, 3r/8 below the waterline
};

// For `displaced_m3` of water of `density` under `gravity`; zero when disabled or dry.
HeaveTerms heave_terms(const HeaveRadiation& radiation, double displaced_m3, double density, double gravity);

}  // namespace lagoon::physics
