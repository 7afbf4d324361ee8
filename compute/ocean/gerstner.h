// Gerstner waves (issue 15; seed 001 §1.2.1, eqs. 6-11): every surface point moves on a circle (an ellipse in
// finite depth is not modelled: the document's eq. 6 form), so crests sharpen and troughs flatten. This is
// the model's CPU side in double precision, the reference for its GPU pass and the query (height, normal and
// velocity at a point) that bodies and probes use. Plain C++.
//
// Eq. 11, with Q_i the steepness of wave i (Q = 1 is eq. 6 as written):
//   x = x0 - Σ Q_i (k_i/|k_i|) A_i sin θ_i,   y = Σ A_i cos θ_i,   θ_i = k_i·x0 - ω_i t + φ_i.
// The horizontal map folds over (the crest loops) once Σ Q_i |k_i| A_i > 1; the model scales every Q_i down
// to keep the sum at most 1 unless told not to.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "ocean/shoaling.h"
#include "ocean/wave_query.h"

namespace lagoon::ocean {

struct GerstnerWave {
  double amplitude_m = 0.5;
  double wavelength_m = 20;
  double direction_deg = 180;  // the direction it travels, compass degrees (as the wind)
  double phase_rad = 0;        // φ
  double steepness = 1;        // Q: 0 = a sum of sines, 1 = the document's circles
  // The height's profile: 0 = eq. 11's A cos θ; p >= 1 = the sum of sines' A ((1 + sin θ)/2)^p (eqs. 2-3),
  // less its mean C(2p, p)/4^p (shared/direct_waves_math.h).
  uint32_t power = 0;
};

struct GerstnerParams {
  std::vector<GerstnerWave> waves;
  GerstnerDispersion dispersion = GerstnerDispersion::Deep;
  double depth_m = 1000;        // D of eq. 8
  double loop_period_s = 0;     // > 0: eq. 10, every ω a multiple of 2π/T (the surface repeats with T)
  bool limit_steepness = true;  // scale the Q_i so that Σ Q k A <= 1 (no loops)
  // The floor the waves feel (ocean/shoaling.h); none: depth_m everywhere.
  std::shared_ptr<const DepthProfile> floor;
  double breaker_index = kBreakerIndex;
  // The random sea when these waves are swell over it: its depth-limited scale and its lattices' moves go in
  // the same table (ocean/shoaling.h).
  RandomSea sea;
};

// One rest point x0 at time t: where it has moved and the surface's local frame there.
struct GerstnerPoint {
  glm::dvec3 position{0.0};  // (x, y, z) of the point that rests at (x0, 0, z0)
  glm::dvec3 normal{0, 1, 0};
  glm::dvec3 velocity{0.0};  // m/s
  double jacobian = 1;       // of the horizontal map x0 -> x: < 0 where the surface loops
};

class GerstnerSurface {
 public:
  explicit GerstnerSurface(GerstnerParams params);

  size_t size() const { return k_.size(); }
  double omega(size_t wave) const { return omega_[wave]; }
  glm::dvec2 wavevector(size_t wave) const { return k_[wave]; }
  double steepness(size_t wave) const { return q_[wave]; }  // after the limit
  const GerstnerParams& params() const { return params_; }
  // The waves' transformation over the floor, or null where no floor is shallow enough to change them.
  const Shoaling* shoaling() const { return shoaling_.get(); }
  const std::shared_ptr<const Shoaling>& shared_shoaling() const { return shoaling_; }
  double profile_mean(size_t wave) const { return mean_[wave]; }  // left out of the height (power > 0)
  // Σ Q_i |k_i| A_i: at most 1 with the limit on.
  double steepness_sum() const;

  // Eq. 11 at the rest point x0.
  GerstnerPoint at_rest(glm::dvec2 x0, double time_s) const;
  // The surface above (x, z): the rest point that moves there (Newton on the horizontal map), then its
  // height, normal and velocity. converged is false where the map has folded.
  WaveSample sample(double time_s, double x, double z) const;

 private:
  // The sums of eq. 11 at a rest point, and the derivatives the point, its normal and Newton need.
  struct Sum {
    glm::dvec2 shift{0.0}, vxz{0.0}, dy{0.0};
    double y = 0, vy = 0, jxx = 1, jxz = 0, jzz = 1;
  };
  Sum sum_at(glm::dvec2 x0, double time_s) const;

  GerstnerParams params_;
  std::shared_ptr<const Shoaling> shoaling_;
  std::vector<glm::dvec2> k_;
  std::vector<double> omega_, q_, mean_;  // mean_: the profile's, left out
};

// The mean of the sum of sines' profile ((1 + sin θ)/2)^p over a period, C(2p, p) / 4^p, left out of the
// height so the sea's mean level stays 0 (0 for p = 0, Gerstner's cos θ).
double sine_profile_mean(uint32_t power);

// ω(k) of the chosen law, before quantisation: sqrt(g k) (eq. 7), sqrt(g k tanh(k D)) (eq. 8), or
// sqrt(g k (1 + k² L²)) (eq. 9, L = sqrt(σ/(ρg)) the capillary length).
double gerstner_omega(GerstnerDispersion law, double k, double depth_m);

// The waves model gerstner uses: params.gerstner.waves, or with spectrum_waves = N, N waves sampled from the
// scene's spectrum with deterministic amplitudes (seed 001 eq. 13, h0 = the spectrum's amplitude, no random
// factor): frequencies on a geometric grid from 0.6 to 4 ω_p, each carrying A = sqrt(2 S(ω) Δω); a direction
// from the spreading D(ω, θ) at a golden-ratio quasi-random quantile; phases from the seed.
std::vector<GerstnerWaveSpec> gerstner_wave_specs(const OceanParams& params);
// The sampling itself: n waves of the scene's spectrum (also the sines' spectrum_waves).
std::vector<GerstnerWaveSpec> spectrum_wave_specs(const OceanParams& params, uint32_t n);

// The scene's Gerstner waves (gerstner_wave_specs) as the cascades hold them: each wave vector moved to the
// nearest one of the lattice 2π m / L of the cascade whose band holds it, so the sum tiles; steepness =
// params.choppiness. cascade_of[i] is the cascade of wave i, or -1 when no band holds it.
std::vector<GerstnerWave> lattice_gerstner_waves(const OceanParams& params,
                                                 std::vector<int>* cascade_of = nullptr);
// The cascade's spectrum holding those waves: h0(k) = A/2 e^{iφ}, ω(k) = ω(-k) of the law, quantised.
CascadeSpectrum gerstner_cascade_spectrum(const OceanParams& params, uint32_t cascade);
// The CPU model of the same waves (choppiness as Q, the params' depth and loop period).
GerstnerParams gerstner_params(const OceanParams& params);

}  // namespace lagoon::ocean
