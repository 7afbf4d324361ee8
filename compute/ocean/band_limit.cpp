#include "ocean/band_limit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lagoon::ocean {

CascadeSpectrum band_limited(const CascadeSpectrum& s, double k_cut) {
  const double k_max = std::min(s.band.k_max, k_cut);
  if (!(k_max > s.band.k_min) || s.resolution == 0) return {};
  const uint32_t n = s.resolution;
  const double dk = 2 * std::numbers::pi / s.patch_size_m;
  // Mode index m carries |k| = dk |m|: the kept ones have |m| < k_max / dk; 4 texels per wavelength need
  // N' >= 4 |m|.
  const double m_limit = k_max / dk;
  uint32_t m = 8;
  while (m < n && double(m) < 4 * m_limit) m *= 2;
  CascadeSpectrum out;
  out.resolution = m;
  out.patch_size_m = s.patch_size_m;
  out.band = {s.band.k_min, k_max};
  out.h0.assign(size_t(m) * m, {0.f, 0.f});
  out.omega.assign(size_t(m) * m, 0.f);
  const auto signed_index = [](uint32_t i, uint32_t size) {
    return i < size / 2 ? int(i) : int(i) - int(size);
  };
  for (uint32_t iz = 0; iz < n; ++iz)
    for (uint32_t ix = 0; ix < n; ++ix) {
      const int mx = signed_index(ix, n), mz = signed_index(iz, n);
      if (dk * std::hypot(double(mx), double(mz)) >= k_max) continue;
      if (std::abs(mx) >= int(m / 2) || std::abs(mz) >= int(m / 2)) continue;  // (cannot happen: m >= 4 |m|)
      const size_t from = size_t(iz) * n + ix;
      const size_t to = size_t((mz + int(m)) % int(m)) * m + size_t((mx + int(m)) % int(m));
      out.h0[to] = s.h0[from];
      out.omega[to] = s.omega[from];
    }
  return out;
}

}  // namespace lagoon::ocean
