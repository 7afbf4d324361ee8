// FFTW (double precision) as the independent CPU reference of the FFT tests and the ocean reference step.
#pragma once
#include <complex>
#include <vector>

namespace lagoon::test {

// In-place 2-D transform of `batches` row-major n x n arrays; inverse = exp(+2πi kn/N), unnormalised.
void fftw_2d(std::vector<std::complex<double>>& data, int n, int batches, bool inverse);

// ||a - b|| / ||b|| over all elements.
double relative_l2(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b);

}  // namespace lagoon::test
