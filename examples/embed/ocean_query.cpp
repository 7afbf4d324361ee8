// Part 1 of the embedding example: Lagoon's ocean with no Vulkan at all. It links Lagoon::ocean only, and the
// install test builds it with a <vulkan/vulkan.h> that #errors first on the include path to prove it.
//
// A physics engine would do this for buoyancy: describe the sea, then ask for the water height, normal and
// surface velocity under its floating bodies at the simulation's time.
#include <cmath>
#include <cstdio>

#include "ocean/ocean_params.h"
#include "ocean/validate.h"
#include "ocean/wave_query.h"

namespace ocean = lagoon::ocean;

int main() {
  // A fresh breeze over 200 m of water; two small cascades keep the first evaluation quick (~10 ms).
  const ocean::OceanParams params{
      .seed = 7,
      .depth_m = 200.0,
      .choppiness = 0.8,
      .spectrum = {.type = ocean::SpectrumType::Jonswap, .wind_speed_mps = 9.0, .wind_direction_deg = 30.0},
      .cascades = {{.patch_size_m = 256.0, .resolution = 64}, {.patch_size_m = 32.0, .resolution = 64}},
  };
  if (auto valid = ocean::validate(params); !valid) {
    std::fprintf(stderr, "embed_ocean: %s\n", valid.error().message.c_str());
    return 1;
  }

  ocean::WaveQuery query(params);
  const double x = 12.5, z = -3.0;  // metres
  double lowest = INFINITY, highest = -INFINITY;
  std::printf("WaveQuery at (x %.1f m, z %.1f m):\n", x, z);
  for (int step = 0; step <= 8; ++step) {
    const double t = 0.25 * step;  // seconds
    const ocean::WaveSample s = query.sample(t, x, z);
    std::printf(
        "  t %5.2f s  height %+.4f m (+-%.1e)  normal (%+.3f %+.3f %+.3f)  velocity (%+.3f %+.3f %+.3f) "
        "m/s\n",
        t, s.height, s.error_bound_m, s.normal.x, s.normal.y, s.normal.z, s.velocity.x, s.velocity.y,
        s.velocity.z);
    if (!std::isfinite(s.height)) {
      std::fprintf(stderr, "embed_ocean: the height at t = %.2f s is not finite\n", t);
      return 1;
    }
    lowest = std::fmin(lowest, s.height);
    highest = std::fmax(highest, s.height);
  }
  // A 9 m/s wind raises waves of decimetres: a surface that did not move in 2 s would mean a broken set-up.
  if (highest - lowest < 1e-3) {
    std::fprintf(stderr, "embed_ocean: the water did not move (height range %.2e m over 2 s)\n",
                 highest - lowest);
    return 1;
  }
  std::printf("height range over 2 s: %.3f m\n", highest - lowest);
  return 0;
}
