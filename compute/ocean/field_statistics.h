// What `lagoon compare` measures from a model's height field (issue 15, docs/models.md), on grids read back
// from the GPU: the significant wave height, the wavevector that carries the most energy, the field's energy
// in bands of |k| against a target spectrum's, and how alike the field is one patch period away (tiling).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "ocean/ocean_params.h"

namespace lagoon::ocean {

// One cascade's heights, row-major [z][x], periodic over `patch_m`.
struct HeightGrid {
  uint32_t n = 0;
  double patch_m = 0;
  std::vector<double> height;
  double at(glm::dvec2 p) const;  // bilinear, periodic
};

// The sea's height at p: every cascade's, summed.
double summed_height(std::span<const HeightGrid> cascades, glm::dvec2 p);

// Hs = 4 σ of the summed field. The cascades hold disjoint bands of |k|, so their variances add: each is
// taken over its own grid's points, where no interpolation damps the short waves.
double significant_height(std::span<const HeightGrid> cascades);

// The correlation coefficient of h(x) and h(x + lag) over the same grid (both axes' lags averaged): 1 where
// the field repeats at that lag.
double tiling_correlation(std::span<const HeightGrid> cascades, double lag_m, uint32_t samples = 256);

// A grid's energy per Fourier mode, |c_k|² with h = Σ c_k e^{ik·x} (so the sum is the mean square height),
// row-major in the DFT's order (element i is mode i < n/2 ? i : i - n).
struct ModeEnergy {
  uint32_t n = 0;
  double patch_m = 0;
  std::vector<double> energy;
  glm::dvec2 wavevector(uint32_t ix, uint32_t iz) const;  // rad/m
};
ModeEnergy mode_energy(const HeightGrid& grid);

// The wavevector of the most energetic mode (either of a ± pair: the one with kz > 0, or kx > 0 on kz = 0).
glm::dvec2 peak_wavevector(const ModeEnergy& e);

// Energy in log-spaced bands of |k| in [k_min, k_max): the measured modes' sum, and the target Ψ(k) Δk²
// summed over the same modes (Ψ integrates to the variance over the plane, ocean/spectrum.h).
struct BandEnergies {
  std::vector<double> k_edges, measured, target;
  double relative_error = 0;  // sqrt(Σ (measured - target)²) / sqrt(Σ target²)
};
BandEnergies band_energies(const ModeEnergy& e, const OceanParams& target, double k_min, double k_max,
                           uint32_t bands = 12);

}  // namespace lagoon::ocean
