#include "ocean/cascade_lattice.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "core/compass.h"
#include "ocean/initial_spectrum.h"

namespace lagoon::ocean {

glm::dvec2 wave_vector(double wavelength_m, double direction_deg) {
  return 2 * std::numbers::pi / wavelength_m * compass::toward_deg(direction_deg);
}

LatticeWave snap_to_cascades(const OceanParams& params, glm::dvec2 k) {
  const std::vector<CascadeBand> bands = cascade_bands(params);
  for (size_t c = 0; c < params.cascades.size(); ++c) {
    const double dk = 2 * std::numbers::pi / params.cascades[c].patch_size_m;
    const glm::dvec2 m = glm::round(k / dk);
    const double length = glm::length(m * dk);
    if (length > 0 && length >= bands[c].k_min && length < bands[c].k_max)
      return {int(c), glm::ivec2(m), m * dk};
  }
  return {-1, glm::ivec2(0), k};
}

size_t mode_index(uint32_t n, long mx, long mz) {
  const long size = long(n);
  return size_t((mz % size + size) % size) * n + size_t((mx % size + size) % size);
}

}  // namespace lagoon::ocean
