// Sediment stirred up from the floor (issue 14, docs/physics.md "Sediment"): a hull or its propeller wash
// that passes within release_height_m of the floor throws up a cloud. Each cloud is a Gaussian puff (the
// puff model of dispersion): the wash lifts it rise_m above the floor; then it drifts with the current,
// sinks at the particles' settling velocity and spreads by turbulent diffusion, σ² = radius² + 2 K age. The
// part of it that has sunk below the floor has settled there, so the water clears over time.
// Every cloud is a closed form of its age: the clouds at any time follow from the stirrers' paths without
// stepping, so a frame at time t shows the same water however it was reached. Plain C++, deterministic.
#pragma once
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

namespace lagoon::physics {

struct SedimentParams {
  double release_height_m = 1.5;    // a hull's lowest point closer to the floor than this stirs it
  double release_g_per_s = 10;      // at the floor; falls linearly to 0 at release_height_m
  double rise_m = 0.8;              // height above the floor of a new cloud's centre
  double radius_m = 0.5;            // a new cloud's standard deviation
  double settling_mps = 0.01;       // the particles' settling velocity (Stokes: fine sand ~0.1 mm)
  double diffusivity_m2_s = 0.005;  // turbulent diffusivity that spreads a cloud
  glm::dvec2 current_mps{0.0};      // the water's drift (x, z)
  double interval_s = 1.0;          // a stirrer releases one cloud per interval, at multiples of it
  double max_age_s = 600;           // older clouds are dropped (long settled at the defaults)
  // The wash's burst (seed 002 §3.4: thrown out radially from a point and rising): a new cloud leaves the
  // floor as a point a fifth of radius_m across and reaches rise_m and radius_m as 1 - e^(-age / burst_s);
  // diffusion and settling go on as before. 0 = born at its full height and size.
  double burst_s = 0.5;
};

// Where a stirrer's lowest point is at time t: (x, y, z), y up, the mean water level at 0.
using StirrerBottom = std::function<glm::dvec3(double)>;
// The floor's depth below the mean water level at (x, z) (> 0 under water).
using FloorDepth = std::function<double(glm::dvec2)>;

struct SedimentPuff {
  uint32_t release = 0;    // which release it is (a hash of the stirrer and its step): the same each frame
  glm::dvec3 centre{0.0};  // world m
  double sigma = 0;        // m
  double mass_g = 0;       // released
  double suspended_g = 0;  // the part above the floor
  double age_s = 0;
};

class SedimentCloud {
 public:
  SedimentCloud(SedimentParams params, FloorDepth floor, std::vector<StirrerBottom> stirrers);

  // Release rate (g/s) of a stirrer whose lowest point is `altitude_m` above the floor: none at or above
  // release_height_m.
  double release_rate(double altitude_m) const;
  // The clouds in the water at time t (those with more than 1e-4 of their mass still suspended).
  std::vector<SedimentPuff> puffs(double time_s) const;
  // A cloud released at `origin` (on the floor under the stirrer) with `mass_g`, `age_s` later.
  SedimentPuff puff(glm::dvec2 origin, double mass_g, double age_s) const;
  // Mass released up to time t, and still suspended at t.
  double released_g(double time_s) const;
  double suspended_g(double time_s) const;
  const SedimentParams& params() const { return params_; }

 private:
  double release_at(size_t stirrer, long long step, glm::dvec2* where) const;

  SedimentParams params_;
  FloorDepth floor_;
  std::vector<StirrerBottom> stirrers_;
};

// Concentration (g/m³) at p of the clouds: zero below the floor.
double sediment_concentration(std::span<const SedimentPuff> puffs, const FloorDepth& floor, glm::dvec3 p);

// The optical depth along a ray and its attenuation-weighted distance (τ, τ t̄) through the clouds, by the
// closed form of shaders/shared/sediment_math.h (what the shaders evaluate), for `attenuation_m2_per_g`.
glm::dvec2 sediment_ray(std::span<const SedimentPuff> puffs, double attenuation_m2_per_g, glm::dvec3 origin,
                        glm::dvec3 dir, double length_m);

// A box holding every puff's reach (centre ± √20 σ, shared/sediment.h): a ray segment that misses it gets
// (0, 0) from sediment_ray, so the shaders test it before their loop over the clouds. Empty (lo > hi)
// without puffs.
struct SedimentBox {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
};
SedimentBox sediment_reach(std::span<const SedimentPuff> puffs);
// Whether origin + t dir, 0 <= t <= length_m, meets `box` (the shaders' test, shared/sediment_math.h).
bool segment_meets(const SedimentBox& box, glm::dvec3 origin, glm::dvec3 dir, double length_m);

}  // namespace lagoon::physics
