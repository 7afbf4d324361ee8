// A plain CPU FFT (radix-2, double, several lines at once) for library code that must not depend on FFTW
// (WaveQuery). FFTW is the reference it is tested against.
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
  // kLanes lines transformed together, element i of line l at [i * kLanes + l].
  static constexpr uint32_t kLanes = 16;
  struct Lanes {
    std::vector<double> re, im;
  };
  void transform_lanes(Lanes& lanes) const;
  uint32_t n_;
  std::vector<std::complex<double>> twiddles_;  // exp(±2πi q/n), q < n/2
  std::vector<uint32_t> bit_reverse_;
};

}  // namespace lagoon::fft
