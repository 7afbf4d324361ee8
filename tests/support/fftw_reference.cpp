#include "support/fftw_reference.h"

#include <fftw3.h>

#include <cmath>

namespace lagoon::test {

void fftw_2d(std::vector<std::complex<double>>& data, int n, int batches, bool inverse) {
  const int dims[2] = {n, n};
  auto* ptr = reinterpret_cast<fftw_complex*>(data.data());
  fftw_plan plan = fftw_plan_many_dft(2, dims, batches, ptr, nullptr, 1, n * n, ptr, nullptr, 1, n * n,
                                      inverse ? FFTW_BACKWARD : FFTW_FORWARD, FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
}

double relative_l2(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b) {
  double diff = 0, ref = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    diff += std::norm(a[i] - b[i]);
    ref += std::norm(b[i]);
  }
  return a.size() == b.size() && ref > 0 ? std::sqrt(diff / ref) : INFINITY;
}

}  // namespace lagoon::test
