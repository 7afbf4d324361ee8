// The four-flow model of light in a water layer (Belyaev, seed section 4, eqs. 4–9): directional flows G+
// (down) and G− (up), diffuse flows F+ (down) and F− (up), as functions of the optical depth τ = εz,
// ε = χ + σ, between the surface (τ = 0) and the bottom (τ0 = εh). Closed form derived in four_flow.cpp.
#pragma once

#include "core/result.h"
#include "optics/surface.h"

namespace lagoon::optics {

struct FourFlowInput {
  double absorption_per_m;  // χ > 0
  double scattering_per_m;  // σ >= 0
  // X1, first Legendre coefficient of the normalised phase function, in [0, 3) (3g for Henyey–Greenstein g).
  // The seed's S = σ(1 − X1/2)/ε turns negative above 2; the model then needs χ + σ(2 − X1) > 0 (else it
  // has no bounded solution and solve_four_flow fails). Flows are guaranteed >= 0 only for X1 <= 1: above 1
  // the directional backscatter S2 = σ(1 − X1)/(2ε) is negative, a sink of F−, and under a bright sun F−(0)
  // comes out negative (it does for X1 = 2.75 in clear water). Forward-peaked phase functions need scaling
  // (e.g. σ(1 − g) with X1 = 0) before they fit this model.
  double phase_x1;
  double depth_m;  // h >= 0 (0 = bottom at the surface)
  SurfaceCoefficients surface;
  BottomCoefficients bottom;
  double e_sun;  // direct irradiance arriving at the surface from above (before t_dd), any unit, >= 0
  double e_sky;  // diffuse irradiance arriving at the surface from above, >= 0
  // D in [1, 4]: the diffuse flows' path length per unit depth, 1/μ̄ for their mean cosine μ̄. The seed's
  // eq. 4 has D = 1 (diffuse light attenuated like a vertical beam); isotropic light has D = 2. Scales the
  // diffuse flows' own loss and exchange (k + S, S), not the light the beams scatter into them
  // (docs/optics.md, "Against measurements").
  double diffuse_path_factor = 1.0;
};

struct FourFlowSolution {
  // Model constants of eq. 4/5: k = χ/ε, S, S1, S2, λ = k + S1 + S2 = 1, λ0 = sqrt(k(k + 2S)), A3 = 1/A4.
  // The seed's A1, A2 are not stored: they are singular at λ0 = 1 (σ = 0); the closed form does not use them.
  double k = 0, s = 0, s1 = 0, s2 = 0, lambda = 1, lambda0 = 0, a3 = 0;
  double diffuse_path = 1;    // D
  double lambda_diffuse = 0;  // D λ0: the rate the free diffuse modes decay at
  double tau0 = 0;            // εh

  // Flows at optical depth τ, clamped to [0, tau0]. Same unit as e_sun/e_sky.
  double g_plus(double tau) const;
  double g_minus(double tau) const;
  double f_plus(double tau) const;
  double f_minus(double tau) const;

 private:
  friend Result<FourFlowSolution> solve_four_flow(const FourFlowInput& input);
  double decay_difference(double t) const;  // (e^{−Λ t} − e^{−t}) / (1 − Λ), Λ = D λ0, finite at Λ = 1
  double clamp_tau(double tau) const;
  double non_negative(double flow) const;

  // Constants of the closed form (four_flow.cpp), each multiplying an exponential that decays away from
  // the boundary it is referred to, so none of them over- or underflows for any τ0.
  double one_minus_decay_ = 0;   // 1 − Λ (for D = 1 computed without cancellation)
  double g0_ = 0, gh_ = 0;       // G+(0), G−(τ0)
  double p_ = 0, q_ = 0;         // forced (particular) response of the diffuse modes to G±
  double u_ = 0, w_ = 0;         // free diffuse modes: down from the surface, up from the bottom
  bool clamp_negative_ = false;  // X1 <= 1: the exact flows are >= 0, so negatives are rounding
};

// Fails, naming the parameter, for χ <= 0, σ < 0, X1 outside [0, 3) or χ + σ(2 − X1) <= 0, h < 0, surface or
// bottom coefficients outside [0, 1], negative irradiance, anything non-finite, and a lossless cavity
// (τ0 = 0 between perfectly reflecting surface and bottom).
Result<FourFlowSolution> solve_four_flow(const FourFlowInput& input);

}  // namespace lagoon::optics
