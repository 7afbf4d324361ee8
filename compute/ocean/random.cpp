#include "ocean/random.h"

#include <cmath>
#include <numbers>

namespace lagoon::ocean {

uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::complex<double> gaussian_pair(uint32_t seed, uint32_t cascade, int32_t mode_x, int32_t mode_z) {
  // Two chained rounds: (seed, cascade) then the mode; each 64-bit word holds one pair losslessly.
  const uint64_t stream = splitmix64((uint64_t{seed} << 32) | cascade);
  const uint64_t mode = (uint64_t{static_cast<uint32_t>(mode_x)} << 32) | static_cast<uint32_t>(mode_z);
  const uint64_t key = splitmix64(stream ^ mode);
  const uint64_t a = splitmix64(key ^ 0x5851f42d4c957f2dull), b = splitmix64(key ^ 0x14057b7ef767814full);
  constexpr double kUnit = 0x1p-53;
  const double u1 = static_cast<double>((a >> 11) + 1) * kUnit;  // (0, 1]: log(u1) is finite
  const double u2 = static_cast<double>(b >> 11) * kUnit;        // [0, 1)
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

}  // namespace lagoon::ocean
