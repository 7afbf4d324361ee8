// The ocean's fields by direct summation of every mode at one point: slow, exact, and independent of the
// FFT and of any interpolation. The reference for queries at arbitrary points.
#pragma once
#include <vector>

#include "ocean/spectral_fields.h"

namespace lagoon::test {

double direct_sum(const std::vector<ocean::CascadeSpectrum>& spectra, ocean::Field field, double time_s,
                  double x, double z);

}  // namespace lagoon::test
