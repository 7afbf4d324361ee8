#include "support/direct_sum.h"

#include <numbers>

namespace lagoon::test {

double direct_sum(const std::vector<ocean::CascadeSpectrum>& spectra, ocean::Field field, double time_s,
                  double x, double z) {
  double sum = 0;
  for (const auto& s : spectra) {
    const uint32_t n = s.resolution;
    const double dk = 2 * std::numbers::pi / s.patch_size_m;
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix) {
        if (s.omega[size_t{iz} * n + ix] == 0 && s.h0[size_t{iz} * n + ix] == std::complex<float>(0) &&
            s.h0[size_t{(n - iz) % n} * n + (n - ix) % n] == std::complex<float>(0))
          continue;  // outside the band: contributes nothing
        const double kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
        const double kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
        sum += (ocean::field_spectrum(s, ix, iz, time_s, field) * std::polar(1.0, kx * x + kz * z)).real();
      }
  }
  return sum;
}

}  // namespace lagoon::test
