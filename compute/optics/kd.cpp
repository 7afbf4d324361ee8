#include "optics/kd.h"

#include <algorithm>
#include <cmath>

#include "optics/four_flow.h"
#include "optics/surface.h"

namespace lagoon::optics {
namespace {

// The four flows in 500 m of the inputs' water over a black floor (deep water), at grid wavelength i, and
// ε to turn metres into optical depth.
struct DeepWater {
  Result<FourFlowSolution> flows;
  double epsilon = 0;
};

DeepWater deep_water(const LutInputs& in, int i, double diffuse_path_factor) {
  const double sigma = in.water.scattering_per_m[i];
  const double particles = std::max(sigma - pure_seawater_scattering()[i], 0.0);
  const SimilarScattering s = similarity_scaled(sigma, sigma > 0 ? 3 * 0.924 * particles / sigma : 0.0);
  return {solve_four_flow({.absorption_per_m = in.water.absorption_per_m[i],
                           .scattering_per_m = s.scattering_per_m,
                           .phase_x1 = s.phase_x1,
                           .depth_m = 500,
                           .surface = surface_coefficients(in.params.ior, sun_zenith_rad(in.sky)),
                           .bottom = lambertian_bottom(0),
                           .e_sun = in.sky.sun[i],
                           .e_sky = in.sky.sky[i],
                           .diffuse_path_factor = diffuse_path_factor}),
          in.water.absorption_per_m[i] + s.scattering_per_m};
}

}  // namespace

double model_kd(const LutInputs& in, int i, double diffuse_path_factor) {
  const DeepWater w = deep_water(in, i, diffuse_path_factor);
  if (!w.flows) return 0;
  auto down = [&](double z) { return w.flows->g_plus(w.epsilon * z) + w.flows->f_plus(w.epsilon * z); };
  return -std::log(down(10.0) / down(5.0)) / 5.0;
}

double model_reflectance(const LutInputs& in, int i, double diffuse_path_factor) {
  const DeepWater w = deep_water(in, i, diffuse_path_factor);
  if (!w.flows) return 0;
  const double down = w.flows->g_plus(0) + w.flows->f_plus(0), up = w.flows->g_minus(0) + w.flows->f_minus(0);
  return down > 0 ? up / down : 0;
}

}  // namespace lagoon::optics
