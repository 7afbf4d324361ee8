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

void CpuFft2d::transform_line(std::complex<double>* line) const {
  for (uint32_t i = 0; i < n_; ++i)
    if (i < bit_reverse_[i]) std::swap(line[i], line[bit_reverse_[i]]);
  for (uint32_t len = 2; len <= n_; len <<= 1) {
    const uint32_t half = len / 2, step = n_ / len;
    for (uint32_t start = 0; start < n_; start += len)
      for (uint32_t k = 0; k < half; ++k) {
        // The product written out: std::complex's operator* checks its result for NaN (C99 Annex G) at
        // every butterfly; for finite data this is the same arithmetic, without the check.
        const std::complex<double> a = line[start + k], x = line[start + k + half], w = twiddles_[k * step];
        const std::complex<double> b(x.real() * w.real() - x.imag() * w.imag(),
                                     x.real() * w.imag() + x.imag() * w.real());
        line[start + k] = a + b;
        line[start + k + half] = a - b;
      }
  }
}

void CpuFft2d::transform(std::vector<std::complex<double>>& data, uint32_t batches, unsigned threads) const {
  const size_t plane = size_t{n_} * n_;
  if (data.size() < plane * batches) throw std::invalid_argument("CpuFft2d: data smaller than the batches");
  // Columns are gathered 16 at a time so each row is read in contiguous runs (a strided walk per column
  // touches a new cache line for every element).
  constexpr uint32_t kBlock = 16;
  auto work = [&](uint32_t first, uint32_t last) {
    std::vector<std::complex<double>> columns(size_t{kBlock} * n_);
    for (uint32_t b = first; b < last; ++b) {
      std::complex<double>* p = data.data() + plane * b;
      for (uint32_t row = 0; row < n_; ++row) transform_line(p + size_t{row} * n_);
      for (uint32_t col0 = 0; col0 < n_; col0 += kBlock) {
        const uint32_t width = std::min(kBlock, n_ - col0);
        for (uint32_t row = 0; row < n_; ++row)
          for (uint32_t c = 0; c < width; ++c) columns[size_t{c} * n_ + row] = p[size_t{row} * n_ + col0 + c];
        for (uint32_t c = 0; c < width; ++c) transform_line(columns.data() + size_t{c} * n_);
        for (uint32_t row = 0; row < n_; ++row)
          for (uint32_t c = 0; c < width; ++c) p[size_t{row} * n_ + col0 + c] = columns[size_t{c} * n_ + row];
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
