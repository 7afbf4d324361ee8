// How Lagoon splits a length-N transform into Stockham passes: two passes for every supported size, radix
// 16 as long as it divides up to 256, radix 32 above. Few passes matter more than arithmetic: on lavapipe
// time follows passes over memory.
#pragma once
#include <cstdint>
#include <vector>

namespace lagoon::fft {

inline constexpr uint32_t kMinSize = 64;
inline constexpr uint32_t kMaxSize = 1024;

bool is_supported_size(uint32_t n);  // power of two in [kMinSize, kMaxSize]

// Radices whose product is n, largest first: 256 -> {16, 16}, 512 -> {32, 16}, 1024 -> {32, 32},
// 64 -> {16, 4}.
std::vector<uint32_t> stockham_radices(uint32_t n);

// exp(+2πi q/n) for q < n as interleaved float pairs, computed in double.
std::vector<float> twiddle_table(uint32_t n);

}  // namespace lagoon::fft
