#include "fft/fft_plan.h"

#include <cmath>
#include <numbers>

namespace lagoon::fft {

bool is_supported_size(uint32_t n) {
  return n >= kMinSize && n <= kMaxSize && (n & (n - 1)) == 0;
}

std::vector<uint32_t> stockham_radices(uint32_t n) {
  // Above 256 a radix-32 pass saves a whole pass over memory: 512 = 32 x 16 and 1024 = 32 x 32 take two
  // passes, where radix 16 and a remainder would take three.
  if (n > 256) return {32, n / 32};
  std::vector<uint32_t> radices;
  while (n % 16 == 0 && n > 1) {
    radices.push_back(16);
    n /= 16;
  }
  if (n > 1) radices.push_back(n);  // 2, 4 or 8 for a power of two
  return radices;
}

std::vector<float> twiddle_table(uint32_t n) {
  std::vector<float> table(2 * size_t{n});
  for (uint32_t q = 0; q < n; ++q) {
    const double angle = 2.0 * std::numbers::pi * double(q) / double(n);
    table[2 * q] = float(std::cos(angle));
    table[2 * q + 1] = float(std::sin(angle));
  }
  return table;
}

}  // namespace lagoon::fft
