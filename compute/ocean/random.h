// Counter-based Gaussian random numbers for the wave modes: each mode's numbers are a pure function of its
// key (seed, cascade, mode), never of iteration order, thread count or grid size, so a parameter change
// elsewhere (resolution, spectrum) keeps every surviving mode's phase.
#pragma once
#include <complex>
#include <cstdint>

namespace lagoon::ocean {

// splitmix64's finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix with full avalanche.
uint64_t splitmix64(uint64_t x);

// ξr + iξi with ξr, ξi independent N(0, 1) (so E|.|² = 2), from two 53-bit uniforms of the hashed key and
// Box-Muller in double. The integer part is bit-exact everywhere; log/cos/sin follow the platform's libm.
std::complex<double> gaussian_pair(uint32_t seed, uint32_t cascade, int32_t mode_x, int32_t mode_z);

}  // namespace lagoon::ocean
