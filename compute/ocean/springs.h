// Model springs (issue 15, seed 001 §1.1.3): the Hooke grid of eqs. 4-5, in double precision. It is the
// reference the GPU step (ocean/gpu/springs_gpu.h) is tested against, and what WaveQuery samples for this
// model. The grid is the first cascade's: its resolution, its patch, periodic, so the field tiles like every
// other model's. Node (i, j) sits at world (i, j) · spacing.
//
// Time: the state after m steps is the surface at t_m = m Δt. Between steps the picture is the straight line
// between x_{m-1} and x_m, which eq. 5's last line makes x_m - v_m (t_m - t): so the state kept for a time t
// is the one after steps_for(t) = floor(t / Δt) + 1 steps.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "ocean/ocean_params.h"
#include "shared/springs.h"

namespace lagoon::ocean {

// At most this many steps are taken to reach one time from the state at hand (a probe at t = 52000 s
// from rest, 1e10 node updates on a 256² grid); later times are refused with the reason.
inline constexpr uint64_t kSpringsMaxCatchUpSteps = 131072;

// The largest stable Δt for the linear grid: semi-implicit Euler is stable while ω_max Δt <= 2, and the
// stiffest mode (the checkerboard) has ω_max² = 8 c / m. Table 1 gives 0.535 s; its Δt = 0.4 s is 75 % of it.
double springs_stability_limit_s(const SpringsParams& p);

// The small-wave frequency (rad/s) of the mode k on the grid: the lattice's sqrt((4 c'/m)(sin²(kx h/2) +
// sin²(kz h/2))), c' = c (1 - L/h), as semi-implicit Euler turns it, (2/Δt) asin(Δt ω/2); the Nyquist
// limit where the step cannot follow.
double springs_omega(const SpringsParams& p, double spacing_m, double kx, double kz);

// Steps to take from rest for the surface at `time_s` (>= 0).
uint64_t springs_steps_for(const SpringsParams& p, double time_s);

// The drops and gusts as the GPU step takes them: accelerations per node, over whole steps.
std::vector<gpu::SpringExcitation> springs_excitations(const OceanParams& params);

class SpringGrid {
 public:
  explicit SpringGrid(const OceanParams& params);

  uint32_t resolution() const { return n_; }
  double spacing_m() const { return spacing_; }
  uint64_t steps() const { return steps_; }
  // (height m, vertical velocity m/s) per node, row-major [j][i].
  const std::vector<glm::dvec2>& state() const { return state_; }

  void step();
  void reset();
  // Steps (from rest again if `steps` is behind) until `steps` steps are done.
  void advance_to(uint64_t steps);
  // The heights and vertical velocities at `time_s`, advancing as needed: x_m - v_m (t_m - t). Before t = 0
  // the grid rests.
  std::vector<glm::dvec2> surface_at(double time_s);
  // Σ ½ m v² + Σ over springs ½ c Δy² (linear springs), J.
  double energy() const;

 private:
  SpringsParams p_;
  uint32_t n_ = 0;
  double spacing_ = 0;
  uint64_t steps_ = 0;
  std::vector<gpu::SpringExcitation> excitations_;
  std::vector<glm::dvec2> state_, next_;
};

}  // namespace lagoon::ocean
