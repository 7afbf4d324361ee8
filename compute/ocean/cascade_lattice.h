// Where an explicit wave lives in the cascades (issue 15's models through the FFT ocean's pipeline): a
// cascade of patch L holds wave vectors 2π m / L only, so a wave is moved to the nearest lattice point of the
// first cascade whose band holds it, and the sum of such waves tiles like the FFT ocean.
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

#include "ocean/ocean_params.h"

namespace lagoon::ocean {

struct LatticeWave {
  int cascade = -1;    // -1: no cascade's band holds it
  glm::ivec2 mode{0};  // m: k = 2π m / L of that cascade
  glm::dvec2 k{0.0};   // rad/m, on the lattice (the asked k when no cascade holds it)
};

// k of a wave `wavelength_m` long travelling toward `direction_deg` (compass degrees, core/compass.h).
glm::dvec2 wave_vector(double wavelength_m, double direction_deg);
LatticeWave snap_to_cascades(const OceanParams& params, glm::dvec2 k);
// Index of mode (mx, mz) in a cascade's n x n arrays ([iz * n + ix], negative modes wrapped).
size_t mode_index(uint32_t n, long mx, long mz);

}  // namespace lagoon::ocean
