// Catmull-Rom weights: WaveQuery's periodic lookups on the cascades' grids and LocalHeights' interpolation
// in time and space use the same cubic.
#pragma once
#include <array>

namespace lagoon::ocean {

// Weights of the samples at offsets -1, 0, 1, 2 for a point at fraction s in [0, 1] between 0 and 1.
inline std::array<double, 4> catmull_rom_weights(double s) {
  const double s2 = s * s, s3 = s2 * s;
  return {0.5 * (-s3 + 2 * s2 - s), 0.5 * (3 * s3 - 5 * s2 + 2), 0.5 * (-3 * s3 + 4 * s2 + s),
          0.5 * (s3 - s2)};
}

}  // namespace lagoon::ocean
