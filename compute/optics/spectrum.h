// The wavelength grid of the optics model: 380-780 nm in 5 nm steps (the CIE tables' own grid).
#pragma once
#include <array>

namespace lagoon::optics {

inline constexpr int kLambdaMinNm = 380;
inline constexpr int kLambdaMaxNm = 780;
inline constexpr int kLambdaStepNm = 5;
inline constexpr int kSamples = (kLambdaMaxNm - kLambdaMinNm) / kLambdaStepNm + 1;  // 81

using Spectrum = std::array<double, kSamples>;

inline constexpr double wavelength_nm(int index) {
  return kLambdaMinNm + kLambdaStepNm * index;
}

// The sample of a wavelength on the grid (the inverse of wavelength_nm for whole grid wavelengths).
inline constexpr int sample_index(int nm) {
  return (nm - kLambdaMinNm) / kLambdaStepNm;
}

}  // namespace lagoon::optics
