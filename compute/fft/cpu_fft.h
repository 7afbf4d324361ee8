// A plain CPU FFT (radix-2, double) for library code that must not depend on FFTW (WaveQuery). FFTW is
// the reference it is tested against.
#pragma once
#include <complex>
#include <cstdint>
#include <vector>

namespace lagoon::fft {

class CpuFft2d {
 public:
  // n: power of two. inverse: exp(+2πi kn/N), unnormalised (as FFTW_BACKWARD).
  CpuFft2d(uint32_t n, bool inverse);
  // In place over `batches` row-major n x n arrays; batches run on `threads` threads (results do not depend
  // on it).
  void transform(std::vector<std::complex<double>>& data, uint32_t batches, unsigned threads = 1) const;
  uint32_t size() const { return n_; }

 private:
  void transform_line(std::complex<double>* line) const;
  uint32_t n_;
  std::vector<std::complex<double>> twiddles_;  // exp(±2πi q/n), q < n/2
  std::vector<uint32_t> bit_reverse_;
};

}  // namespace lagoon::fft
