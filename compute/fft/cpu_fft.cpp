#include "fft/cpu_fft.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

namespace lagoon::fft {

CpuFft2d::CpuFft2d(uint32_t n, bool inverse) : n_(n), twiddles_(n / 2), bit_reverse_(n) {
  if (n < 2 || (n & (n - 1)) != 0) throw std::invalid_argument("CpuFft2d: size must be a power of two");
  const double sign = inverse ? 1.0 : -1.0;
  for (uint32_t q = 0; q < n / 2; ++q) twiddles_[q] = std::polar(1.0, sign * 2.0 * std::numbers::pi * q / n);
  uint32_t bits = 0;
  while ((1u << bits) < n) ++bits;
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t r = 0;
    for (uint32_t b = 0; b < bits; ++b) r |= ((i >> b) & 1u) << (bits - 1 - b);
    bit_reverse_[i] = r;
  }
}

void CpuFft2d::transform_lanes(Lanes& lanes) const {
  constexpr uint32_t L = kLanes;
  double* re = lanes.re.data();
  double* im = lanes.im.data();
  for (uint32_t i = 0; i < n_; ++i)
    if (const uint32_t j = bit_reverse_[i]; i < j)
      for (uint32_t l = 0; l < L; ++l) {
        std::swap(re[i * L + l], re[j * L + l]);
        std::swap(im[i * L + l], im[j * L + l]);
      }
  for (uint32_t len = 2; len <= n_; len <<= 1) {
    const uint32_t half = len / 2, step = n_ / len;
    for (uint32_t start = 0; start < n_; start += len)
      for (uint32_t k = 0; k < half; ++k) {
        // The radix-2 butterfly with the product written out (std::complex's operator* checks its result
        // for NaN at every butterfly, C99 Annex G): the same operations in the same order for every lane.
        const double wr = twiddles_[k * step].real(), wi = twiddles_[k * step].imag();
        double* __restrict ar = re + size_t{start + k} * L;
        double* __restrict ai = im + size_t{start + k} * L;
        double* __restrict br = re + size_t{start + k + half} * L;
        double* __restrict bi = im + size_t{start + k + half} * L;
        for (uint32_t l = 0; l < L; ++l) {
          const double xr = br[l], xi = bi[l];
          const double tr = xr * wr - xi * wi, ti = xr * wi + xi * wr;
          const double pr = ar[l], pi = ai[l];
          ar[l] = pr + tr;
          ai[l] = pi + ti;
          br[l] = pr - tr;
          bi[l] = pi - ti;
        }
      }
  }
}

void CpuFft2d::transform(std::vector<std::complex<double>>& data, uint32_t batches, unsigned threads) const {
  const size_t plane = size_t{n_} * n_;
  if (data.size() < plane * batches) throw std::invalid_argument("CpuFft2d: data smaller than the batches");
  // Rows, then columns, kLanes lines at a time: each line's elements interleaved with the others' (real and
  // imaginary parts apart) so the butterflies run on vector registers. Columns are then read in contiguous
  // runs too (a strided walk per column touches a new cache line for every element).
  constexpr uint32_t L = kLanes;
  auto work = [&](uint32_t first, uint32_t last) {
    Lanes lanes{std::vector<double>(size_t{L} * n_), std::vector<double>(size_t{L} * n_)};
    for (uint32_t b = first; b < last; ++b) {
      std::complex<double>* p = data.data() + plane * b;
      for (uint32_t row0 = 0; row0 < n_; row0 += L) {
        const uint32_t width = std::min(L, n_ - row0);
        // Rows of zeros stay zeros: a band-limited spectrum (WaveQuery's, issue 35) fills half its rows.
        if (std::all_of(p + size_t{row0} * n_, p + size_t{row0 + width} * n_,
                        [](std::complex<double> c) { return c.real() == 0 && c.imag() == 0; }))
          continue;
        for (uint32_t l = 0; l < width; ++l)
          for (uint32_t i = 0; i < n_; ++i) {
            lanes.re[size_t{i} * L + l] = p[size_t{row0 + l} * n_ + i].real();
            lanes.im[size_t{i} * L + l] = p[size_t{row0 + l} * n_ + i].imag();
          }
        transform_lanes(lanes);
        for (uint32_t l = 0; l < width; ++l)
          for (uint32_t i = 0; i < n_; ++i)
            p[size_t{row0 + l} * n_ + i] = {lanes.re[size_t{i} * L + l], lanes.im[size_t{i} * L + l]};
      }
      for (uint32_t col0 = 0; col0 < n_; col0 += L) {
        const uint32_t width = std::min(L, n_ - col0);
        for (uint32_t row = 0; row < n_; ++row)
          for (uint32_t l = 0; l < width; ++l) {
            lanes.re[size_t{row} * L + l] = p[size_t{row} * n_ + col0 + l].real();
            lanes.im[size_t{row} * L + l] = p[size_t{row} * n_ + col0 + l].imag();
          }
        transform_lanes(lanes);
        for (uint32_t row = 0; row < n_; ++row)
          for (uint32_t l = 0; l < width; ++l)
            p[size_t{row} * n_ + col0 + l] = {lanes.re[size_t{row} * L + l], lanes.im[size_t{row} * L + l]};
      }
    }
  };
  threads = std::max(1u, std::min(threads, batches));
  if (threads == 1) return work(0, batches);
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back(work, batches * t / threads, batches * (t + 1) / threads);
  for (auto& th : pool) th.join();
}

}  // namespace lagoon::fft
